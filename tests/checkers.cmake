# tests for the checkers layer

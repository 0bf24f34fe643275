# tests for the grid layer

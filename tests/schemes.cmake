# tests for the schemes layer

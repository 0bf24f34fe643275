# tests for the geometry layer

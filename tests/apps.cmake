# tests for the apps layer

# tests for the grid layer
dualhex_add_test(test_grid_refinement SOURCES test_grid_refinement.cpp DEPS dualhex::grid)

# tests for the grid layer
dualhex_add_test(test_grid_leaf_file SOURCES test_grid_leaf_file.cpp DEPS dualhex::grid)
dualhex_add_test(test_grid_leaf SOURCES test_grid_leaf.cpp DEPS dualhex::grid)
dualhex_add_test(test_grid_refinement SOURCES test_grid_refinement.cpp DEPS dualhex::grid)
dualhex_add_test(test_grid_symmetry SOURCES test_grid_symmetry.cpp DEPS dualhex::grid)
dualhex_add_test(test_grid_configurations SOURCES test_grid_configurations.cpp DEPS dualhex::grid)
dualhex_add_test(test_grid_shared_data SOURCES test_grid_shared_data.cpp DEPS dualhex::grid)
dualhex_add_test(test_grid_complex SOURCES test_grid_complex.cpp DEPS dualhex::grid)
dualhex_add_test(test_grid_leaf_file_hostile SOURCES test_grid_leaf_file_hostile.cpp DEPS dualhex::grid)

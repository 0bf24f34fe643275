dualhex_add_test(test_cube_symmetry SOURCES test_cube_symmetry.cpp DEPS dualhex::topology)

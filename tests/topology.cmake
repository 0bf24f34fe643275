dualhex_add_test(test_cube_symmetry SOURCES test_cube_symmetry.cpp DEPS dualhex::topology)
dualhex_add_test(test_topology_complex SOURCES test_topology_complex.cpp DEPS dualhex::topology)
dualhex_add_test(test_topology_validation SOURCES test_topology_validation.cpp DEPS dualhex::topology)
dualhex_add_test(test_topology_properties SOURCES test_topology_properties.cpp DEPS dualhex::topology)

# tests for the checkers layer
dualhex_add_test(test_checkers_configurations SOURCES test_checkers_configurations.cpp DEPS dualhex::checkers)
dualhex_add_test(test_compositional SOURCES test_compositional.cpp DEPS dualhex::checkers)
dualhex_add_test(test_compositional_weak SOURCES test_compositional_weak.cpp DEPS dualhex::checkers)
dualhex_add_test(test_compositional_boundary SOURCES test_compositional_boundary.cpp DEPS dualhex::checkers)
dualhex_add_test(test_class_check SOURCES test_class_check.cpp DEPS dualhex::checkers)
dualhex_add_test(test_congruence_check SOURCES test_congruence_check.cpp DEPS dualhex::checkers)
dualhex_add_test(test_root_boundary_grids SOURCES test_root_boundary_grids.cpp DEPS dualhex::checkers)
dualhex_add_test(test_compositional_weak_stars SOURCES test_compositional_weak_stars.cpp DEPS dualhex::checkers)

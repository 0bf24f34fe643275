# weakly balanced grids: configuration space, weak rule, MR elements
dualhex_add_test(test_weak SOURCES test_weak.cpp DEPS dualhex::checkers dualhex::schemes)

# tests for installation into grids: the clipped dual, `dualhex install`, random-grid properties
dualhex_add_test(test_install_clipped_dual SOURCES test_install_clipped_dual.cpp DEPS dualhex::checkers)

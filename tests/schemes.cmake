# tests for the schemes layer
dualhex_add_test(test_schemes_format SOURCES test_schemes_format.cpp DEPS dualhex::schemes)
dualhex_add_test(test_schemes_check SOURCES test_schemes_check.cpp DEPS dualhex::schemes)
dualhex_add_test(test_schemes_library SOURCES test_schemes_library.cpp DEPS dualhex::schemes)
dualhex_add_test(test_schemes_embedded SOURCES test_schemes_embedded.cpp DEPS dualhex::schemes)

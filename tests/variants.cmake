# tests for the chain-crossing variants (schemes/variants.hpp, checkers/variants_report.hpp)
dualhex_add_test(test_variants SOURCES test_variants.cpp DEPS dualhex::checkers)

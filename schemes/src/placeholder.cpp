namespace dualhex { int schemes_placeholder() { return 0; } }

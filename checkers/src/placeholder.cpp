namespace dualhex { int checkers_placeholder() { return 0; } }

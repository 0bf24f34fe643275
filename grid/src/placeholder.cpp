namespace dualhex { int grid_placeholder() { return 0; } }

# tests for the geometry layer
dualhex_add_test(test_geometry_surface SOURCES test_geometry_surface.cpp DEPS dualhex::geometry)

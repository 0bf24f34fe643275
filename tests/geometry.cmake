# tests for the geometry layer
dualhex_add_test(test_geometry_surface SOURCES test_geometry_surface.cpp DEPS dualhex::geometry)
dualhex_add_test(test_geometry_aabb SOURCES test_geometry_aabb.cpp DEPS dualhex::geometry)
dualhex_add_test(test_geometry_octree SOURCES test_geometry_octree.cpp DEPS dualhex::geometry)

# tests for the geometry layer
dualhex_add_test(test_geometry_surface SOURCES test_geometry_surface.cpp DEPS dualhex::geometry)
dualhex_add_test(test_geometry_aabb SOURCES test_geometry_aabb.cpp DEPS dualhex::geometry)
dualhex_add_test(test_geometry_octree SOURCES test_geometry_octree.cpp DEPS dualhex::geometry)
dualhex_add_test(test_geometry_output SOURCES test_geometry_output.cpp DEPS dualhex::geometry)

# Read-back of the hex writers with meshio (python3-meshio), skipped (77) without it.
add_executable(geometry_write_samples geometry_write_samples.cpp)
target_link_libraries(geometry_write_samples PRIVATE dualhex::geometry)
find_program(DUALHEX_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
find_program(DUALHEX_PYTHON3 NAMES python3)
if(DUALHEX_PYTHON3)
  add_test(NAME geometry_meshio_readback
           COMMAND ${DUALHEX_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/geometry_meshio_readback.py
                   $<TARGET_FILE:geometry_write_samples> ${CMAKE_CURRENT_BINARY_DIR}/geometry_meshio_readback)
  set_tests_properties(geometry_meshio_readback PROPERTIES SKIP_RETURN_CODE 77)
endif()
dualhex_add_test(test_geometry_quality SOURCES test_geometry_quality.cpp DEPS dualhex::geometry)
# Strict readers and the self-intersection check against hostile input (issue 15).
dualhex_add_test(test_geometry_readers_hostile SOURCES test_geometry_readers_hostile.cpp DEPS dualhex::geometry)
dualhex_add_test(test_geometry_self_intersection SOURCES test_geometry_self_intersection.cpp DEPS dualhex::geometry)

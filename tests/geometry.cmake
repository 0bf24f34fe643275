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
dualhex_add_test(test_geometry_hex_topology SOURCES test_geometry_hex_topology.cpp DEPS dualhex::geometry dualhex::mesher)  # mesher: the default torus
dualhex_add_test(test_geometry_manifold_repair SOURCES test_geometry_manifold_repair.cpp DEPS dualhex::geometry)
dualhex_add_test(test_geometry_surface_distance SOURCES test_geometry_surface_distance.cpp DEPS dualhex::geometry)
if(TARGET mesh_quality)  # the independent benchmark's measurements (built with DUALHEX_BUILD_BENCH)
  dualhex_add_test(test_bench_mesh_quality SOURCES test_bench_mesh_quality.cpp DEPS dualhex::geometry)
  target_compile_definitions(test_bench_mesh_quality PRIVATE MESH_QUALITY_EXE="$<TARGET_FILE:mesh_quality>")
  add_dependencies(test_bench_mesh_quality mesh_quality)
endif()

# Size control (surface octree criteria, the mesh at a size, the CLI's size options) and
# per-cell data (writers, the mesher's per-hex levels).
dualhex_add_test(test_geometry_size_control SOURCES test_geometry_size_control.cpp DEPS dualhex::mesher)
target_compile_definitions(test_geometry_size_control PRIVATE DUALHEX_EXE="$<TARGET_FILE:dualhex>")
add_dependencies(test_geometry_size_control dualhex)
dualhex_add_test(test_geometry_cell_data SOURCES test_geometry_cell_data.cpp DEPS dualhex::mesher)
dualhex_add_test(test_geometry_features SOURCES test_geometry_features.cpp DEPS dualhex::geometry)
# Strict readers and the self-intersection check against hostile input (issue 15).
dualhex_add_test(test_geometry_readers_hostile SOURCES test_geometry_readers_hostile.cpp DEPS dualhex::geometry)
dualhex_add_test(test_geometry_self_intersection SOURCES test_geometry_self_intersection.cpp DEPS dualhex::geometry)
# The parallel surface octree against the serial walk (a private header of the layer).
dualhex_add_test(test_geometry_octree_threads SOURCES test_geometry_octree_threads.cpp DEPS dualhex::geometry TBB::tbb)
target_include_directories(test_geometry_octree_threads PRIVATE ${PROJECT_SOURCE_DIR}/geometry/src)

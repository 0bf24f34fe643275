# tests for the surface-to-hex pipeline (`dualhex mesh`, mesher/mesh_pipeline.hpp)
dualhex_add_test(test_mesh_pipeline SOURCES test_mesh_pipeline.cpp DEPS dualhex::mesher)

# `dualhex mesh` as a process
dualhex_add_test(test_mesh_cli SOURCES test_mesh_cli.cpp DEPS nlohmann_json::nlohmann_json)
target_compile_definitions(test_mesh_cli PRIVATE DUALHEX_EXE="$<TARGET_FILE:dualhex>")
add_dependencies(test_mesh_cli dualhex)

# Output read back with meshio (python3-meshio), skipped (77) without it.
find_program(DUALHEX_PYTHON3 NAMES python3)
if(DUALHEX_PYTHON3)
  add_test(NAME mesh_meshio_readback
           COMMAND ${DUALHEX_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/mesh_meshio_readback.py
                   $<TARGET_FILE:dualhex> ${CMAKE_CURRENT_BINARY_DIR}/mesh_meshio_readback ${DUALHEX_SHARED_DATA})
  set_tests_properties(mesh_meshio_readback PROPERTIES SKIP_RETURN_CODE 77)
endif()

# Output read back with gmsh (python3-gmsh): no skip, a missing gmsh fails the test, since
# scripts/debian-packages.txt installs it. Without python3 the test fails too (not found).
find_program(DUALHEX_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
find_program(DUALHEX_PYTHON3 NAMES python3)
set(_dualhex_python3 "${DUALHEX_PYTHON3}")
if(NOT DUALHEX_PYTHON3)
  set(_dualhex_python3 python3)
endif()
add_test(NAME mesh_gmsh_readback
         COMMAND ${_dualhex_python3} ${CMAKE_CURRENT_SOURCE_DIR}/mesh_gmsh_readback.py
                 $<TARGET_FILE:dualhex> ${CMAKE_CURRENT_BINARY_DIR}/mesh_gmsh_readback ${DUALHEX_SHARED_DATA})

# the features stage and the crease measurement (mesher/features.hpp, feature_report.hpp)
dualhex_add_test(test_mesher_features SOURCES test_mesher_features.cpp DEPS dualhex::mesher)
# the mesher's core, pad, optimise and check stages on hand-made meshes
dualhex_add_test(test_mesher_optimise SOURCES test_mesher_optimise.cpp DEPS dualhex::mesher)
dualhex_add_test(test_mesher_optimise_release SOURCES test_mesher_optimise_release.cpp DEPS dualhex::mesher)
dualhex_add_test(test_mesher_place_guard SOURCES test_mesher_place_guard.cpp DEPS dualhex::mesher)
dualhex_add_test(test_mesher_hex_energy SOURCES test_mesher_hex_energy.cpp DEPS dualhex::mesher)
dualhex_add_test(test_mesher_pad SOURCES test_mesher_pad.cpp DEPS dualhex::mesher)
# the pad on folded cores, the bad-hex diagnostic (mesher/pad_diagnosis.hpp)
dualhex_add_test(test_mesher_pad_quality SOURCES test_mesher_pad_quality.cpp DEPS dualhex::mesher)
# the features stage's refusal of inverting snaps, the optimiser's deterministic work budget
dualhex_add_test(test_mesher_feature_refusal SOURCES test_mesher_feature_refusal.cpp DEPS dualhex::mesher)
dualhex_add_test(test_mesher_budget SOURCES test_mesher_budget.cpp DEPS dualhex::mesher TBB::tbb)
dualhex_add_test(test_mesher_core_topology SOURCES test_mesher_core_topology.cpp DEPS dualhex::mesher)
dualhex_add_test(test_mesher_core_fill SOURCES test_mesher_core_fill.cpp DEPS dualhex::mesher)
# the refine stage: unresolved places, local octree splits, a slab thinner than its cells
dualhex_add_test(test_mesher_refine SOURCES test_mesher_refine.cpp DEPS dualhex::mesher)
# the core cleanup before the pad (mesher/core_cleanup.hpp)
dualhex_add_test(test_mesher_core_cleanup SOURCES test_mesher_core_cleanup.cpp DEPS dualhex::mesher)
# `dualhex mesh --threads N`: the same bytes and report at 1, 2 and 4 threads (issue 13)
dualhex_add_test(test_mesher_threads SOURCES test_mesher_threads.cpp DEPS nlohmann_json::nlohmann_json)
target_compile_definitions(test_mesher_threads PRIVATE DUALHEX_EXE="$<TARGET_FILE:dualhex>")
add_dependencies(test_mesher_threads dualhex)

# docs/render_mesh.py, the README's mesh picture: a cut block drawn, bad input refused.
add_test(NAME docs_render_mesh
         COMMAND ${_dualhex_python3} ${CMAKE_CURRENT_SOURCE_DIR}/render_mesh_test.py
                 ${PROJECT_SOURCE_DIR}/docs/render_mesh.py ${CMAKE_CURRENT_BINARY_DIR}/docs_render_mesh)

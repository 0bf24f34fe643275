# tests for the surface-to-hex pipeline (`dualhex mesh`, geometry/mesh_pipeline.hpp)
dualhex_add_test(test_mesh_pipeline SOURCES test_mesh_pipeline.cpp DEPS dualhex::geometry)

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

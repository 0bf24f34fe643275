# tests for the audit layer (readers, checks, `dualhex audit`)
dualhex_add_test(test_audit_readers SOURCES test_audit_readers.cpp DEPS dualhex::audit dualhex::geometry)
dualhex_add_test(test_audit_checks SOURCES test_audit_checks.cpp DEPS dualhex::audit dualhex::geometry)
# `dualhex audit` as a process, with the standalone checker on its certificates
dualhex_add_test(test_audit_cli SOURCES test_audit_cli.cpp DEPS dualhex::geometry nlohmann_json::nlohmann_json)
target_compile_definitions(test_audit_cli PRIVATE DUALHEX_EXE="$<TARGET_FILE:dualhex>"
                                                  DUALHEX_PROOF_CHECKER="$<TARGET_FILE:dualhex-proof-checker>")
add_dependencies(test_audit_cli dualhex dualhex-proof-checker)
dualhex_add_test(test_audit_robustness SOURCES test_audit_robustness.cpp DEPS dualhex::audit dualhex::geometry)
# Files written by meshio (VTK 5.1 ASCII/binary, VTU ascii/base64, MEDIT) audited by the CLI;
# skipped (77) without python3-meshio. DUALHEX_PYTHON3 is found in geometry.cmake.
if(DUALHEX_PYTHON3)
  add_test(NAME audit_meshio_interop
           COMMAND ${DUALHEX_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/audit_meshio_interop.py
                   $<TARGET_FILE:dualhex> ${CMAKE_CURRENT_BINARY_DIR}/audit_meshio_interop)
  set_tests_properties(audit_meshio_interop PROPERTIES SKIP_RETURN_CODE 77)
endif()

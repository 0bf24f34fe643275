# tests for the audit layer (readers, checks, `dualhex audit`)
dualhex_add_test(test_audit_readers SOURCES test_audit_readers.cpp DEPS dualhex::audit dualhex::geometry)
dualhex_add_test(test_audit_checks SOURCES test_audit_checks.cpp DEPS dualhex::audit dualhex::geometry)
# `dualhex audit` as a process, with the standalone checker on its certificates
dualhex_add_test(test_audit_cli SOURCES test_audit_cli.cpp DEPS dualhex::geometry nlohmann_json::nlohmann_json)
target_compile_definitions(test_audit_cli PRIVATE DUALHEX_EXE="$<TARGET_FILE:dualhex>"
                                                  DUALHEX_PROOF_CHECKER="$<TARGET_FILE:dualhex-proof-checker>")
add_dependencies(test_audit_cli dualhex dualhex-proof-checker)
dualhex_add_test(test_audit_robustness SOURCES test_audit_robustness.cpp DEPS dualhex::audit dualhex::geometry)

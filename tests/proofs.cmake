# tests for proofs/: the shipped certificates, their freshness, the checker under mutation

# The independent checker re-checks the shipped certificates (no dualhex code involved).
add_test(NAME proofs_shipped_certificates
  COMMAND dualhex-proof-checker ${PROJECT_SOURCE_DIR}/proofs/certificates/manifest)
set_tests_properties(proofs_shipped_certificates PROPERTIES PASS_REGULAR_EXPRESSION "VERIFIED: ")

# Freshness (regenerate, compare with the manifest) and adversarial mutations.
dualhex_add_test(test_proofs_certificates SOURCES test_proofs_certificates.cpp
  DEPS dualhex::checkers dualhex::schemes dualhex::topology)
target_compile_definitions(test_proofs_certificates PRIVATE
  DUALHEX_PROOF_CHECKER="$<TARGET_FILE:dualhex-proof-checker>")
add_dependencies(test_proofs_certificates dualhex-proof-checker)

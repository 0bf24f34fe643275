# tests for proofs/: the shipped certificates, their freshness, the checker under mutation

# The independent checker re-checks the shipped certificates (no dualhex code involved), one
# test per manifest: elements + strong tori, weak tori, crossing variants.
function(dualhex_check_shipped name manifest)
  add_test(NAME ${name} COMMAND dualhex-proof-checker ${PROJECT_SOURCE_DIR}/proofs/certificates/${manifest})
  set_tests_properties(${name} PROPERTIES PASS_REGULAR_EXPRESSION "VERIFIED: ")
endfunction()
dualhex_check_shipped(proofs_shipped_certificates manifest)
dualhex_check_shipped(proofs_shipped_weak_certificates weak/manifest)
dualhex_check_shipped(proofs_shipped_variant_certificates variants/manifest)
dualhex_check_shipped(proofs_shipped_window_certificates windows/manifest)

# Freshness (regenerate, compare with the manifest) and adversarial mutations.
dualhex_add_test(test_proofs_certificates SOURCES test_proofs_certificates.cpp
  DEPS dualhex::checkers dualhex::schemes dualhex::topology)
target_compile_definitions(test_proofs_certificates PRIVATE
  DUALHEX_PROOF_CHECKER="$<TARGET_FILE:dualhex-proof-checker>")
add_dependencies(test_proofs_certificates dualhex-proof-checker)

# Hostile inputs (issue 15): folds, int64-extreme coordinates, non-terminating and huge inputs,
# manifests that switch checks off. Needs only the checker binary.
dualhex_add_test(test_proofs_checker_hostile SOURCES test_proofs_checker_hostile.cpp)
target_compile_definitions(test_proofs_checker_hostile PRIVATE
  DUALHEX_PROOF_CHECKER="$<TARGET_FILE:dualhex-proof-checker>")
add_dependencies(test_proofs_checker_hostile dualhex-proof-checker)

# tests for proofs/: the shipped certificates, their freshness, the checker under mutation

# The independent checker re-checks the shipped certificates (no dualhex code involved), one
# test per manifest: elements + strong tori, weak tori, crossing variants, windows, root
# boundary, four-level grids, weak stars, the corner pair's witness stars, weak root-surface stars.
function(dualhex_check_shipped name manifest)
  add_test(NAME ${name} COMMAND dualhex-proof-checker ${PROJECT_SOURCE_DIR}/proofs/certificates/${manifest})
  set_tests_properties(${name} PROPERTIES PASS_REGULAR_EXPRESSION "VERIFIED: ")
endfunction()
dualhex_check_shipped(proofs_shipped_certificates manifest)
dualhex_check_shipped(proofs_shipped_weak_certificates weak/manifest)
dualhex_check_shipped(proofs_shipped_variant_certificates variants/manifest)
dualhex_check_shipped(proofs_shipped_window_certificates windows/manifest)
dualhex_check_shipped(proofs_shipped_boundary_certificates boundary/manifest)
dualhex_check_shipped(proofs_shipped_weak_spread_certificates weak_spread/manifest)
dualhex_check_shipped(proofs_shipped_weak_star_certificates weak_stars/manifest)
dualhex_check_shipped(proofs_shipped_weak_corner_star_certificates weak_corner_stars/manifest)
dualhex_check_shipped(proofs_shipped_weak_root_star_certificates weak_root_stars/manifest)

# Freshness (regenerate, compare with the manifest) and adversarial mutations.
dualhex_add_test(test_proofs_certificates SOURCES test_proofs_certificates.cpp test_proofs_freshness.cpp
  test_proofs_tampering.cpp
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

# Fuzzing the checker (libFuzzer + ASan + UBSan, proofs/fuzz/): only where clang++ links
# -fsanitize=fuzzer (Debian: clang, libfuzzer-14-dev); the harness includes the checker's source.
# The CTest run is bounded to 45 s;
# bench/run_fuzz.sh runs longer. Crashes land in build/proofs/fuzz-artifacts/.
find_program(DUALHEX_CLANGXX NAMES clang++ clang++-14)
set(dualhex_fuzz_found OFF)
if(DUALHEX_CLANGXX)
  set(probe ${CMAKE_BINARY_DIR}/dualhex-fuzz-probe)
  file(WRITE ${probe}.cpp "#include <cstddef>\n#include <cstdint>\nextern \"C\" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }\n")
  execute_process(COMMAND ${DUALHEX_CLANGXX} -fsanitize=fuzzer ${probe}.cpp -o ${probe} RESULT_VARIABLE probe_failed OUTPUT_QUIET ERROR_QUIET)
  if(NOT probe_failed)
    set(dualhex_fuzz_found ON)
  endif()
endif()
option(DUALHEX_FUZZ "Build and run the libFuzzer harness of the proof checker" ${dualhex_fuzz_found})
if(DUALHEX_FUZZ)
  set(fuzz_dir ${CMAKE_BINARY_DIR}/proofs)
  set(fuzz_bin ${fuzz_dir}/dualhex-checker-fuzz)
  set(checker_src ${PROJECT_SOURCE_DIR}/proofs/checker/checker.cpp)
  set(harness_src ${PROJECT_SOURCE_DIR}/proofs/fuzz/checker_fuzz.cpp)
  add_custom_command(OUTPUT ${fuzz_bin}
    COMMAND ${CMAKE_CXX_COMPILER_LAUNCHER} ${DUALHEX_CLANGXX} -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined
            -fno-sanitize-recover=undefined ${harness_src} -o ${fuzz_bin}
    DEPENDS ${checker_src} ${harness_src} COMMENT "Building the proof checker fuzzer (clang, libFuzzer)" VERBATIM)
  add_custom_command(OUTPUT ${fuzz_dir}/fuzz-seeds/manifest
    COMMAND ${CMAKE_COMMAND} -DSHIPPED=${PROJECT_SOURCE_DIR}/proofs/certificates -DOUT=${fuzz_dir}/fuzz-seeds
            -P ${PROJECT_SOURCE_DIR}/proofs/fuzz/make_seeds.cmake
    DEPENDS ${PROJECT_SOURCE_DIR}/proofs/fuzz/make_seeds.cmake ${PROJECT_SOURCE_DIR}/proofs/certificates/elements.cert
            ${PROJECT_SOURCE_DIR}/proofs/certificates/weak_stars/stars-0000-0499.cert VERBATIM)
  add_custom_target(dualhex-checker-fuzz ALL DEPENDS ${fuzz_bin} ${fuzz_dir}/fuzz-seeds/manifest)
  file(MAKE_DIRECTORY ${fuzz_dir}/fuzz-corpus ${fuzz_dir}/fuzz-artifacts)
  add_test(NAME proofs_checker_fuzz COMMAND ${fuzz_bin} -max_total_time=45 -timeout=10 -rss_limit_mb=2048 -max_len=8192
           -artifact_prefix=${fuzz_dir}/fuzz-artifacts/ ${fuzz_dir}/fuzz-corpus ${fuzz_dir}/fuzz-seeds)
  set_tests_properties(proofs_checker_fuzz PROPERTIES TIMEOUT 120)
endif()

// libFuzzer harness for the independent proof checker: the checker's source is included here
// (its main renamed), and every input is checked by the checker's own functions as a
// certificate file and as a manifest (whose files do not exist), with output discarded. Built
// by tests/proofs.cmake when clang++ accepts -fsanitize=fuzzer (DUALHEX_FUZZ);
// bench/run_fuzz.sh runs it longer.
#include <cstddef>
#include <cstdint>

#define main dualhex_proof_checker_main
#include "../checker/checker.cpp"
#undef main

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::cout.setstate(std::ios::badbit);  // the verdicts are not the point here: no output
    const std::string text(reinterpret_cast<const char*>(data), size);
    Totals file, manifest;
    check_file("fuzz", text, file);
    manifest.budget = 0;
    check_manifest("/nonexistent-dualhex-fuzz/manifest", text, manifest);
    return 0;
}

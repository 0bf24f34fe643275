// libFuzzer harness for the independent proof checker (proofs/checker/checker.cpp, compiled
// with -DDUALHEX_CHECKER_FUZZ, which replaces its main by dualhex_checker_fuzz_one): every
// input is checked as a certificate file and as a manifest. Built by tests/proofs.cmake when
// clang++ accepts -fsanitize=fuzzer (DUALHEX_FUZZ); bench/run_fuzz.sh runs it longer.
#include <cstddef>
#include <cstdint>

extern "C" int dualhex_checker_fuzz_one(const char* data, std::size_t size);

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    dualhex_checker_fuzz_one(reinterpret_cast<const char*>(data), size);
    return 0;
}

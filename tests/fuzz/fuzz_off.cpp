// libFuzzer harness: the strict OFF reader (geometry/src/read_off.cpp), see fuzz_surface.hpp.
#include "fuzz_surface.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return dualhex::fuzz::read_surface_bytes(data, size, dualhex::geometry::detail::read_off, "fuzz.off");
}

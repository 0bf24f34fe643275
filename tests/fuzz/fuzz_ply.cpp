// libFuzzer harness: the strict PLY reader (geometry/src/read_ply.cpp), see fuzz_surface.hpp.
#include "fuzz_surface.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return dualhex::fuzz::read_surface_bytes(data, size, dualhex::geometry::detail::read_ply, "fuzz.ply");
}

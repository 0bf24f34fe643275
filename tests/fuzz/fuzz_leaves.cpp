// libFuzzer harness: parse_leaves (grid/src/leaf_file.cpp) on arbitrary bytes. Any outcome
// but a LeafGrid or an InputError (a crash, a sanitizer report, another exception, a hang)
// is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "dualhex/grid/input_error.hpp"
#include "dualhex/grid/leaf_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const dualhex::LeafGrid grid = dualhex::parse_leaves(text, "fuzz.leaves");
        // A grid that parsed must format and parse back to the same leaves.
        const dualhex::LeafGrid again = dualhex::parse_leaves(dualhex::format_leaves(grid), "again.leaves");
        if (again.size() != grid.size()) __builtin_trap();
    } catch (const dualhex::InputError&) {
    }
    return 0;
}

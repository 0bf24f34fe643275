#pragma once
// Internal: the 12 edges of a hex in VTK_HEXAHEDRON order, and an edge's key.
#include <array>
#include <cstdint>
#include <utility>

namespace dualhex::mesher::detail {

constexpr std::array<std::array<int, 2>, 12> kHexEdges{{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                        {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

/// The unordered pair {a, b} as one key (smaller id in the high half).
[[nodiscard]] inline std::uint64_t edge_key(int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace dualhex::mesher::detail

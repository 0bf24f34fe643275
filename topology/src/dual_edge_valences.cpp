// The dual edge valences of a clipped dual (clipped_dual.hpp).
#include <algorithm>

#include "dualhex/topology/clipped_dual.hpp"

namespace dualhex {

std::map<int, std::size_t> clipped_dual_edge_valences(const ClippedDual& d) {
    // The 12 edges of a VTK hexahedron.
    static constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                          {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    std::vector<std::uint64_t> keys;
    keys.reserve(12 * d.hexes.size());
    for (const auto& h : d.hexes)
        for (const auto& [i, j] : kEdges) {
            std::uint32_t a = h[static_cast<std::size_t>(i)], b = h[static_cast<std::size_t>(j)];
            if (d.kind[a] != DualVertexKind::Cell && d.kind[b] != DualVertexKind::Cell) continue;
            if (a > b) std::swap(a, b);
            keys.push_back(std::uint64_t{a} << 32 | b);
        }
    std::sort(keys.begin(), keys.end());
    std::map<int, std::size_t> h;
    for (std::size_t i = 0; i < keys.size();) {
        std::size_t j = i;
        while (j < keys.size() && keys[j] == keys[i]) ++j;
        ++h[static_cast<int>(j - i)];
        i = j;
    }
    return h;
}

}  // namespace dualhex

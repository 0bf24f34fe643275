// Level of each clipped-dual hex (cell_levels.hpp).
#include "dualhex/mesher/cell_levels.hpp"

#include <algorithm>
#include <array>

namespace dualhex::mesher {
namespace {

// The finest-level cell indices along one axis whose closed interval contains coordinate
// p (lattice units, a finest cell spans `unit`): one index inside a cell, two on a cell
// boundary; only those inside [0, n).
std::vector<std::int64_t> cells_around(std::int64_t p, std::int64_t unit, std::int64_t n) {
    std::vector<std::int64_t> out;
    const std::int64_t c = p / unit;
    if (p % unit == 0 && c - 1 >= 0 && c - 1 < n) out.push_back(c - 1);
    if (c >= 0 && c < n) out.push_back(c);
    return out;
}

}  // namespace

std::vector<int> dual_hex_levels(const ClippedDual& dual, const InstallResult& installed, const LeafGrid& grid) {
    const int max_level = installed.max_level;
    const std::int64_t n = std::int64_t{1} << max_level;
    std::vector<int> levels;
    levels.reserve(dual.hexes.size());
    for (VertexHandle v : dual.primal_vertex) {
        const LatticePoint& p = installed.complex.position(v);
        std::array<std::vector<std::int64_t>, 3> around;
        for (int a = 0; a < 3; ++a) around[a] = cells_around(p[a], installed.unit, n);
        int level = 0;
        for (std::int64_t i : around[0])
            for (std::int64_t j : around[1])
                for (std::int64_t k : around[2])
                    if (const auto leaf = grid.locate(Leaf{max_level, i, j, k}))
                        level = std::max(level, grid.leaf(*leaf).level);
        levels.push_back(level);
    }
    return levels;
}

}  // namespace dualhex::mesher

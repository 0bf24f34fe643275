#include "dualhex/grid/grid_symmetry.hpp"

#include <algorithm>
#include <vector>

namespace dualhex {

Leaf apply(const CubeSymmetry& s, const Leaf& leaf) {
    const std::int64_t n = leaf.extent();
    const LatticePoint lo{leaf.i, leaf.j, leaf.k};
    const LatticePoint a = s.apply_about(lo, n);
    const LatticePoint b = s.apply_about(lo + LatticePoint{1, 1, 1}, n);
    return {leaf.level, std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}

LeafGrid apply(const CubeSymmetry& s, const LeafGrid& grid) {
    std::vector<Leaf> moved;
    moved.reserve(grid.size());
    std::vector<int> lines;
    for (std::size_t n = 0; n < grid.size(); ++n) {
        moved.push_back(apply(s, grid.leaf(n)));
        if (grid.line(n) > 0) lines.push_back(grid.line(n));
    }
    if (lines.size() != moved.size()) lines.clear();
    return LeafGrid(std::move(moved), grid.source(), std::move(lines));
}

}  // namespace dualhex

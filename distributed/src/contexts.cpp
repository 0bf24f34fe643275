// Planned context queries and the contexts they give (contexts.hpp).
#include "contexts.hpp"

#include <algorithm>
#include <unordered_set>

#include "dualhex/grid/cell_map.hpp"
#include "dualhex/install/leaf_contexts.hpp"

namespace dualhex::dist {

std::vector<std::uint64_t> context_points(const std::vector<Leaf>& leaves) {
    // The octant cubes, deduplicated: neighbouring leaves of one level share most of theirs.
    CellMap<char> cubes(leaves.size() * 4 + 16);
    std::vector<Leaf> order;
    for (const Leaf& leaf : leaves) {
        if (leaf.level == 0) continue;
        const std::int64_t n = std::int64_t{1} << (leaf.level - 1);
        std::int64_t lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            const std::int64_t x = leaf.coord(a);
            const std::int64_t p = ((x & 1) == 0 ? x : x + 1) / 2;  // application point, level L-1 units
            // Cubes p-2 .. p+1; mirrored cubes outside the root land inside this range too.
            lo[a] = std::max<std::int64_t>(p - 2, 0);
            hi[a] = std::min<std::int64_t>(p + 1, n - 1);
        }
        for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
            for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
                for (std::int64_t k = lo[2]; k <= hi[2]; ++k) {
                    const Leaf cube{leaf.level - 1, i, j, k};
                    if (cubes.insert(cube, 1).second) order.push_back(cube);
                }
    }
    std::unordered_set<std::uint64_t> seen;
    std::vector<std::uint64_t> out;
    out.reserve(order.size() * 8);
    for (const Leaf& cube : order)
        for (const Leaf& child : children(cube)) {
            const auto c = qcorner(child);
            const std::uint64_t m = morton(c[0], c[1], c[2]);
            if (seen.insert(m).second) out.push_back(m);
        }
    return out;
}

std::vector<LeafContext> gather_contexts(const std::vector<Leaf>& leaves, const LevelOracle& oracle, OutsideRoot outside) {
    const SubdividedQuery query = [&oracle](const Leaf& cell) { return oracle.is_subdivided(cell); };
    std::vector<LeafContext> out;
    out.reserve(leaves.size());
    for (const Leaf& leaf : leaves) out.push_back(leaf_context(leaf, query, outside));
    return out;
}

}  // namespace dualhex::dist

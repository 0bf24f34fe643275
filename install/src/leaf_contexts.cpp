// Leaf contexts: the fast scattered index (context_index.hpp) and the direct reference.
#include "dualhex/install/leaf_contexts.hpp"

#include "context_index.hpp"
#include "dualhex/grid/predicates.hpp"

namespace dualhex {

namespace detail {

// Reflect a cell coordinate across the root faces until it lies in [0, n).
std::int64_t mirror(std::int64_t c, std::int64_t n) {
    while (c < 0 || c >= n) c = c < 0 ? -1 - c : 2 * n - 1 - c;
    return c;
}

// The leaf's application point and direction (level-L units).
void frame_of(const Leaf& leaf, LeafContext& ctx) {
    for (int a = 0; a < 3; ++a) {
        const std::int64_t x = leaf.coord(a);
        const bool even = (x & 1) == 0;
        ctx.application_point[a] = even ? x : x + 1;
        ctx.direction[static_cast<std::size_t>(a)] = even ? 1 : -1;
    }
}

// Weak balance: for each inner edge of the leaf whose two adjacent faces are interfaces,
// is the leaf-sized cell sharing that edge (its diagonal neighbour) refined twice, i.e. does
// it hold leaves two or more levels finer? (Pairing: a cell's children are all leaves or all
// subdivided, so its first child tells.) Only concave edges can need it, so only they are
// looked up.
void set_edge_two_finer(const SubdividedQuery& is_subdivided, const Leaf& leaf, OutsideRoot outside, LeafContext& ctx) {
    const std::int64_t cells = std::int64_t{1} << leaf.level;
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        int fb[3] = {0, 0, 0}, fc[3] = {0, 0, 0};
        fb[b] = -1;
        fc[c] = -1;
        if (!ctx.fine(fb[0], fb[1], fb[2]) || !ctx.fine(fc[0], fc[1], fc[2])) continue;
        Leaf cell{leaf.level, 0, 0, 0};
        bool inside = true;
        for (int t = 0; t < 3; ++t) {
            const int local = t == a ? 0 : -1;
            std::int64_t x = ctx.application_point[t] +
                             (ctx.direction[static_cast<std::size_t>(t)] > 0 ? local : -local - 1);
            if (x < 0 || x >= cells) {
                inside = false;
                x = mirror(x, cells);
            }
            (t == 0 ? cell.i : t == 1 ? cell.j : cell.k) = x;
        }
        if (!inside && outside == OutsideRoot::Coarse) continue;
        if (is_subdivided(cell) && is_subdivided(children(cell)[0])) ctx.set_two_finer_across_edge(a);
    }
}

}  // namespace detail

using detail::ContextIndex;
using detail::frame_of;
using detail::mirror;
using detail::set_edge_two_finer;

std::vector<LeafContext> leaf_contexts(const LeafGrid& grid, OutsideRoot outside) {
    const ContextIndex index(grid, outside);
    std::vector<LeafContext> out;
    out.reserve(grid.size());
    for (const Leaf& leaf : grid.leaves()) out.push_back(index.context(leaf));
    return out;
}

LeafContext leaf_context(const LeafGrid& grid, std::size_t n, OutsideRoot outside) {
    return leaf_context(grid.leaf(n), [&grid](const Leaf& cell) { return grid.is_subdivided(cell); }, outside);
}

LeafContext leaf_context(const Leaf& leaf, const SubdividedQuery& is_subdivided, OutsideRoot outside) {
    LeafContext ctx;
    if (leaf.level == 0) return ctx;
    frame_of(leaf, ctx);
    const std::int64_t cells = std::int64_t{1} << (leaf.level - 1);
    for (int i = -2; i <= 1; ++i)
        for (int j = -2; j <= 1; ++j)
            for (int k = -2; k <= 1; ++k) {
                const int local[3] = {i, j, k};
                Leaf cube{leaf.level - 1, 0, 0, 0};
                bool inside = true;
                for (int a = 0; a < 3; ++a) {
                    const int w = ctx.direction[static_cast<std::size_t>(a)] > 0 ? local[a] : -1 - local[a];
                    std::int64_t c = ctx.application_point[a] / 2 + w;
                    if (c < 0 || c >= cells) {
                        inside = false;
                        c = mirror(c, cells);
                    }
                    (a == 0 ? cube.i : a == 1 ? cube.j : cube.k) = c;
                }
                if (!inside && outside == OutsideRoot::Coarse) continue;
                bool fine = true;  // covered by leaves finer than the leaf: every child subdivided
                for (const Leaf& child : children(cube)) fine = fine && is_subdivided(child);
                if (fine) ctx.set_fine(i, j, k);
            }
    set_edge_two_finer(is_subdivided, leaf, outside, ctx);
    return ctx;
}

}  // namespace dualhex

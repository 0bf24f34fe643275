#pragma once
// Internal: the fast per-leaf contexts. Every fine octant cube is scattered once to the
// (at most 64) application points whose 4x4x4 neighbourhood contains it, so a leaf's
// context is one hash lookup (leaf_contexts.hpp describes what a context holds).
#include <array>
#include <cstdint>

#include "dualhex/grid/cell_map.hpp"
#include "dualhex/install/install.hpp"
#include "dualhex/install/leaf_contexts.hpp"

namespace dualhex::detail {

/// Reflects a cell coordinate across the root faces until it lies in [0, n).
[[nodiscard]] std::int64_t mirror(std::int64_t c, std::int64_t n);
/// Sets the leaf's application point and direction (level-L units).
void frame_of(const Leaf& leaf, LeafContext& ctx);
/// Weak balance: marks the inner edges whose diagonal neighbour holds leaves two or more
/// levels finer (leaf_contexts.cpp).
void set_edge_two_finer(const SubdividedQuery& is_subdivided, const Leaf& leaf, OutsideRoot outside, LeafContext& ctx);

// World neighbourhood masks per (level L, application point / 2), for every application
// point some fine octant cube reaches (absent: all coarse).
class ContextIndex {
public:
    ContextIndex(const LeafGrid& grid, OutsideRoot outside)
        : subdivided_([g = &grid](const Leaf& cell) { return g->is_subdivided(cell); }),
          outside_(outside), masks_(grid.size() / 4 + 16) {
        for (const Leaf& node : grid.interior_nodes()) {
            if (node.level == 0 || child_index(node) != 0) continue;
            // Leaves of level node.level see parent(node) as a fine octant cube (pairing: all
            // of node's siblings are subdivided too).
            scatter(masks_, node.level, parent(node));
        }
    }

    [[nodiscard]] LeafContext context(const Leaf& leaf) const {
        LeafContext ctx;
        if (leaf.level == 0) return ctx;
        frame_of(leaf, ctx);
        const LatticePoint& P = ctx.application_point;
        if (const std::uint64_t* m = masks_.find(Leaf{leaf.level, P.x / 2, P.y / 2, P.z / 2}))
            ctx.neighbourhood = to_local_neighbourhood(*m, ctx.direction);
        set_edge_two_finer(subdivided_, leaf, outside_, ctx);
        return ctx;
    }

private:
    // Marks octant cube c (level L - 1) in the masks of the level-L application points
    // whose 4x4x4 neighbourhood contains it (and its mirror images across the root faces).
    void scatter(CellMap<std::uint64_t>& masks, int L, const Leaf& c) {
        const std::int64_t n = std::int64_t{1} << (L - 1);
        std::array<std::array<std::int64_t, 5>, 3> images{};
        std::array<int, 3> count{};
        for (int a = 0; a < 3; ++a) {
            auto& img = images[static_cast<std::size_t>(a)];
            int& k = count[static_cast<std::size_t>(a)];
            img[static_cast<std::size_t>(k++)] = c.coord(a);
            if (outside_ == OutsideRoot::Mirror)
                for (std::int64_t x : {std::int64_t{-2}, std::int64_t{-1}, n, n + 1})
                    if (mirror(x, n) == c.coord(a) && x != c.coord(a)) img[static_cast<std::size_t>(k++)] = x;
        }
        for (int ix = 0; ix < count[0]; ++ix)
            for (int iy = 0; iy < count[1]; ++iy)
                for (int iz = 0; iz < count[2]; ++iz) {
                    const std::int64_t cx = images[0][static_cast<std::size_t>(ix)],
                                       cy = images[1][static_cast<std::size_t>(iy)],
                                       cz = images[2][static_cast<std::size_t>(iz)];
                    for (int w = 0; w < 64; ++w) {
                        const std::int64_t vx = cx - ((w & 3) - 2), vy = cy - (((w >> 2) & 3) - 2),
                                           vz = cz - (((w >> 4) & 3) - 2);
                        if (vx < 0 || vy < 0 || vz < 0 || vx > n || vy > n || vz > n) continue;
                        *masks.insert(Leaf{L, vx, vy, vz}, 0).first |= std::uint64_t{1} << w;
                    }
                }
    }

    SubdividedQuery subdivided_;
    OutsideRoot outside_;
    CellMap<std::uint64_t> masks_;
};

}  // namespace dualhex::detail

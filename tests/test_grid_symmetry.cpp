// A cube symmetry moves a grid onto a grid with the same tiling, pairing and balance and
// the same leaf counts per level.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "dualhex/grid/grid_symmetry.hpp"
#include "dualhex/grid/refinement.hpp"
#include "test_grid_generators.hpp"

using namespace dualhex;
using dualhex::testing::gen_octree;

TEST(GridSymmetry, MovesALeafInsideTheRoot) {
    const auto mirror_x = CubeSymmetry({0, 1, 2}, {-1, 1, 1});
    EXPECT_EQ(apply(mirror_x, Leaf{2, 0, 1, 3}), (Leaf{2, 3, 1, 3}));
    const auto swap_xy = CubeSymmetry({1, 0, 2}, {1, 1, 1});
    EXPECT_EQ(apply(swap_xy, Leaf{3, 1, 6, 2}), (Leaf{3, 6, 1, 2}));
    EXPECT_EQ(apply(CubeSymmetry{}, Leaf{5, 7, 8, 9}), (Leaf{5, 7, 8, 9}));
}

RC_GTEST_PROP(GridSymmetry, PreservesPredicatesAndCounts, ()) {
    const LeafGrid g = *gen_octree(5);
    const auto s = CubeSymmetry::from_index(*rc::gen::inRange(0, 48));
    RC_LOG() << "symmetry " << s.to_string();
    for (const LeafGrid& grid : {g, pair(g, Balance::Weak)}) {
        const LeafGrid moved = apply(s, grid);  // throws unless it tiles
        RC_ASSERT(moved.counts_per_level() == grid.counts_per_level());
        RC_ASSERT(is_paired(moved).ok == is_paired(grid).ok);
        RC_ASSERT(is_strongly_balanced(moved).ok == is_strongly_balanced(grid).ok);
        RC_ASSERT(is_weakly_balanced(moved).ok == is_weakly_balanced(grid).ok);
        // Balancing commutes with the symmetry (the least refinement is unique).
        RC_ASSERT(balance(moved, Balance::Strong).size() == balance(grid, Balance::Strong).size());
        RC_ASSERT(apply(s.inverse(), moved).leaves() == grid.leaves());
    }
}

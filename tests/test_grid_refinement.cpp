// Balancing and pairing: the predicates on hand-made grids (they must be able to fail),
// and properties of balance/pair on random octrees.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

#include "dualhex/grid/refinement.hpp"
#include "test_grid_generators.hpp"

using namespace dualhex;
using dualhex::testing::gen_octree;
using dualhex::testing::require;

namespace {

// Refined towards the centre of the root: split the root, then its child 1 1 1 1, then
// repeatedly the child touching the root's centre (2 2 2 2, 3 4 4 4, ...). The finest
// leaf 3 4 4 4 touches all 7 level-1 leaves at the centre: faces with 3 of them.
LeafGrid centre_refined(int depth) {
    std::vector<Leaf> leaves;
    Leaf cell{};
    for (int level = 0; level < depth; ++level) {
        const auto kids = children(cell);
        const int keep = level == 0 ? 7 : 0;
        for (int c = 0; c < 8; ++c)
            if (c != keep) leaves.push_back(kids[c]);
        cell = kids[keep];
    }
    leaves.push_back(cell);
    return LeafGrid(std::move(leaves));
}

// Every leaf of `coarse` is a leaf of `fine` or subdivided there: `fine` only refines.
bool only_refines(const LeafGrid& coarse, const LeafGrid& fine) {
    for (const Leaf& l : coarse.leaves())
        if (!fine.find(l) && !fine.is_subdivided(l)) return false;
    return true;
}

// In a least balanced refinement, each node split by balancing (absent from the input)
// whose children are leaves is needed: some leaf two levels finer than the node touches
// it through a constrained contact, i.e. a child's neighbour outside the node is subdivided.
bool split_was_needed(const LeafGrid& grid, const Leaf& node, Balance mode) {
    for (const Leaf& child : children(node))
        for (const Offset& d : neighbour_offsets(mode)) {
            const Leaf n = neighbour(child, d);
            if (n.valid() && parent(n) != node && grid.is_subdivided(n)) return true;
        }
    return false;
}

void require_minimal(const LeafGrid& input, const LeafGrid& out, Balance mode) {
    for (const Leaf& l : out.leaves()) {
        if (l.level == 0 || child_index(l) != 0) continue;
        const Leaf node = parent(l);
        if (input.is_subdivided(node)) continue;
        bool all_leaves = true;
        for (const Leaf& c : children(node)) all_leaves = all_leaves && out.find(c).has_value();
        if (all_leaves && !split_was_needed(out, node, mode))
            RC_FAIL("unnecessary split of " + to_string(node) + " in\n" + format_leaves(out));
    }
}

// Brute force over all pairs, from boxes at a common level: the independent oracle for
// is_balanced. Returns whether some pair in a constrained contact differs by >= 2 levels.
bool brute_force_unbalanced(const LeafGrid& grid, Balance mode) {
    const int top = grid.max_level();
    for (std::size_t a = 0; a < grid.size(); ++a)
        for (std::size_t b = 0; b < grid.size(); ++b) {
            if (grid.leaf(a).level < grid.leaf(b).level + 2) continue;
            const LeafBox x = box_at(grid.leaf(a), top), y = box_at(grid.leaf(b), top);
            int positive = 0;
            bool touching = true;
            for (int axis = 0; axis < 3; ++axis) {
                const auto overlap = std::min(x.hi[axis], y.hi[axis]) - std::max(x.lo[axis], y.lo[axis]);
                touching = touching && overlap >= 0;
                positive += overlap > 0;
            }
            if (touching && (mode == Balance::Strong || positive == 2)) return true;
        }
    return false;
}

}  // namespace

TEST(GridPredicates, DetectUnbalancedAndUnpaired) {
    const LeafGrid g = centre_refined(3);  // levels 1 and 3 touch at the root centre
    const auto strong = is_strongly_balanced(g);
    ASSERT_FALSE(strong.ok);
    EXPECT_NE(strong.message.find("not strongly balanced: leaves 3 "), std::string::npos) << strong.message;
    EXPECT_NE(strong.message.find("differ by 2 levels"), std::string::npos) << strong.message;
    EXPECT_FALSE(is_weakly_balanced(g).ok);
    EXPECT_FALSE(is_paired(g).ok);  // 1 1 1 1 is subdivided, its siblings are leaves

    const LeafGrid l2 = centre_refined(2);
    EXPECT_TRUE(is_strongly_balanced(l2).ok);
    EXPECT_TRUE(is_paired(pair_only(l2)).ok);

    // Split one level-2 leaf of a uniform level-2 grid's neighbour: unpaired.
    std::vector<Leaf> leaves;
    for (const Leaf& c : children(Leaf{}))
        if (c != Leaf{1, 0, 0, 0}) leaves.push_back(c);
    for (const Leaf& c : children(Leaf{1, 0, 0, 0}))
        if (c != Leaf{2, 1, 1, 1}) leaves.push_back(c);
    for (const Leaf& c : children(Leaf{2, 1, 1, 1})) leaves.push_back(c);
    const LeafGrid unpaired(leaves);
    const auto p = is_paired(unpaired);
    ASSERT_FALSE(p.ok);
    EXPECT_NE(p.message.find("leaf 1 1 0 0 has sibling 1 0 0 0 subdivided"), std::string::npos) << p.message;
    // A uniform grid is paired.
    const auto eight = children(Leaf{});
    EXPECT_TRUE(is_paired(LeafGrid(std::vector<Leaf>(eight.begin(), eight.end()))).ok);
}

TEST(GridPredicates, WeakAllowsEdgeAndVertexContacts) {
    // Level-1 leaf 1 1 1 0 touches the corner leaf (level 3) only along... build a grid
    // where only an edge contact is unbalanced: refine leaf 1 0 0 0 down to level 3 at
    // its corner towards 1 1 1 0.
    std::vector<Leaf> leaves;
    for (const Leaf& c : children(Leaf{}))
        if (c != Leaf{1, 0, 0, 0}) leaves.push_back(c);
    for (const Leaf& c : children(Leaf{1, 0, 0, 0}))
        if (c != Leaf{2, 1, 1, 0}) leaves.push_back(c);
    for (const Leaf& c : children(Leaf{2, 1, 1, 0})) leaves.push_back(c);
    const LeafGrid g(leaves);
    // Leaf 3 3 3 0 touches 1 1 1 0 along an edge only; it shares faces with 1 1 0 0 and 1 0 1 0.
    EXPECT_FALSE(is_strongly_balanced(g).ok);
    EXPECT_FALSE(is_weakly_balanced(g).ok);
    const LeafGrid weak = balance(g, Balance::Weak), strong = balance(g, Balance::Strong);
    EXPECT_TRUE(is_weakly_balanced(weak).ok);
    EXPECT_LT(weak.size(), strong.size());
    EXPECT_FALSE(is_strongly_balanced(weak).ok);  // the edge contact stays unbalanced
}

TEST(GridRefinement, KnownLeastBalancing) {
    // Strong: all 7 level-1 leaves touch 3 4 4 4 and split: 7*8 + 7 + 8 = 71 leaves.
    // Weak: only the 3 sharing a face with a level-3 leaf split: 4 + (24 + 7) + 8 = 43.
    const LeafGrid g = centre_refined(3);
    const LeafGrid s = balance(g, Balance::Strong);
    const LeafGrid w = balance(g, Balance::Weak);
    EXPECT_EQ(s.size(), 71u);
    EXPECT_EQ(w.size(), 43u);
    EXPECT_EQ(w.counts_per_level(), (std::vector<std::size_t>{0, 4, 31, 8}));
    EXPECT_TRUE(is_strongly_balanced(s).ok);
    EXPECT_TRUE(is_weakly_balanced(w).ok);
    EXPECT_FALSE(is_strongly_balanced(w).ok);
    EXPECT_EQ(balance(s, Balance::Strong).size(), s.size());  // idempotent
    EXPECT_TRUE(only_refines(g, s));
}

RC_GTEST_PROP(GridRefinement, BalancingIsLeastAndCorrect, ()) {
    const LeafGrid g = *gen_octree(5);
    const LeafGrid strong = balance(g, Balance::Strong);
    const LeafGrid weak = balance(g, Balance::Weak);
    require(is_strongly_balanced(strong), strong, "balance(Strong)");
    require(is_weakly_balanced(weak), weak, "balance(Weak)");
    RC_ASSERT(only_refines(g, strong));
    RC_ASSERT(only_refines(g, weak));
    RC_ASSERT(only_refines(weak, strong));  // strong constraints include the weak ones
    RC_ASSERT(weak.size() <= strong.size());
    require_minimal(g, strong, Balance::Strong);
    require_minimal(g, weak, Balance::Weak);
    if (is_strongly_balanced(g).ok) RC_ASSERT(strong.size() == g.size());
}

RC_GTEST_PROP(GridRefinement, PairingKeepsBalance, ()) {
    const LeafGrid g = *gen_octree(5);
    const LeafGrid paired_only = pair_only(g);
    require(is_paired(paired_only), paired_only, "pair_only");
    RC_ASSERT(only_refines(g, paired_only));
    for (const Balance mode : {Balance::Strong, Balance::Weak}) {
        const LeafGrid p = pair(g, mode);
        require(is_paired(p), p, "pair");
        require(is_balanced(p, mode), p, "pair keeps balance");
        RC_ASSERT(only_refines(g, p));
        RC_ASSERT(only_refines(balance(g, mode), p));
        RC_ASSERT(pair(p, mode).size() == p.size());  // a fixed point
    }
}

RC_GTEST_PROP(GridRefinement, TilingAlwaysHolds, ()) {
    const LeafGrid g = *gen_octree(5);
    // Re-validate the outputs from scratch through the file format.
    for (const LeafGrid& out : {balance(g, Balance::Strong), balance(g, Balance::Weak), pair(g, Balance::Strong)}) {
        try {
            const LeafGrid again = parse_leaves(format_leaves(out), "roundtrip");
            RC_ASSERT(again.size() == out.size());
        } catch (const std::exception& e) {
            RC_FAIL(std::string("not a tiling: ") + e.what());
        }
    }
}

RC_GTEST_PROP(GridPredicates, BalanceAgreesWithBruteForce, ()) {
    // Weakly balanced grids exercise the case "weak holds, strong fails".
    const LeafGrid raw = *gen_octree(4);
    const LeafGrid g = *rc::gen::element(raw, balance(raw, Balance::Weak));
    for (const Balance mode : {Balance::Strong, Balance::Weak}) {
        const auto check = is_balanced(g, mode);
        RC_ASSERT(check.ok == !brute_force_unbalanced(g, mode));
        if (!check.ok) {  // the named pair really is >= 2 levels apart
            RC_ASSERT(g.leaf(*check.first).level >= g.leaf(*check.second).level + 2);
        }
    }
    RC_TAG(is_strongly_balanced(g).ok, is_weakly_balanced(g).ok);
}

// The oracle for is_paired: every leaf's 7 siblings are leaves, each looked up.
RC_GTEST_PROP(GridPredicates, PairedAgreesWithBruteForce, ()) {
    const LeafGrid raw = *gen_octree(4);
    const LeafGrid g = *rc::gen::element(raw, pair_only(raw));
    bool paired = true;
    for (const Leaf& leaf : g.leaves())
        if (leaf.level > 0)
            for (const Leaf& sibling : children(parent(leaf))) paired = paired && g.find(sibling).has_value();
    const auto check = is_paired(g);
    RC_ASSERT(check.ok == paired);
    if (!check.ok) RC_ASSERT(g.leaf(*check.second).level > g.leaf(*check.first).level);  // a finer leaf in a sibling
    RC_TAG(paired);
}

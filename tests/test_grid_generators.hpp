#pragma once
// RapidCheck generators for octrees, shared by the grid tests.
//
// A random octree is a split tree (a leaf, or 8 subtrees), generated to a random depth.
// Shrinking acts on the tree (a subtree shrinks towards a leaf, the 8 children shrink
// element-wise, the count stays 8), so every shrink is again a valid octree.
#include <rapidcheck.h>

#include <ostream>
#include <vector>

#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/grid/predicates.hpp"

namespace dualhex {

// Counterexamples print as leaf files (RapidCheck finds this by ADL).
inline void showValue(const LeafGrid& grid, std::ostream& os) { os << "\n" << format_leaves(grid); }

}  // namespace dualhex

namespace dualhex::testing {

struct SplitTree {
    std::vector<SplitTree> kids;  // empty: a leaf; otherwise exactly 8
};

inline rc::Gen<SplitTree> gen_split_tree(int depth) {
    if (depth == 0) return rc::gen::just(SplitTree{});
    auto split = rc::gen::build<SplitTree>(
        rc::gen::set(&SplitTree::kids, rc::gen::container<std::vector<SplitTree>>(8, gen_split_tree(depth - 1))));
    // Leaf first: RapidCheck shrinks weightedOneOf towards earlier alternatives.
    return rc::gen::weightedOneOf<SplitTree>({{1, rc::gen::just(SplitTree{})}, {1, split}});
}

inline void collect_leaves(const SplitTree& t, const Leaf& cell, std::vector<Leaf>& out) {
    if (t.kids.empty()) {
        out.push_back(cell);
        return;
    }
    const auto kids = children(cell);
    for (std::size_t c = 0; c < 8; ++c) collect_leaves(t.kids[c], kids[c], out);
}

inline LeafGrid to_grid(const SplitTree& t) {
    std::vector<Leaf> leaves;
    collect_leaves(t, Leaf{}, leaves);
    return LeafGrid(std::move(leaves));
}

/// Random octrees of depth 2..max_depth (the root is always split once).
/// Fixed at the nominal size: RapidCheck scales inRange (hence weightedOneOf) by size, which
/// would make every tree a single split for most of the run.
inline rc::Gen<LeafGrid> gen_octree(int max_depth = 5) {
    return rc::gen::resize(rc::kNominalSize, rc::gen::mapcat(rc::gen::inRange(2, max_depth + 1), [](int depth) {
        return rc::gen::map(rc::gen::container<std::vector<SplitTree>>(8, gen_split_tree(depth - 1)),
                            [](std::vector<SplitTree> kids) { return to_grid(SplitTree{std::move(kids)}); });
    }));
}

/// Fails the property with the check's message and the grid as a leaf file.
inline void require(const GridCheck& check, const LeafGrid& grid, const char* what) {
    if (check.ok) return;
    RC_LOG() << what << ": " << check.message << "\n" << format_leaves(grid);
    RC_FAIL(std::string(what) + ": " + check.message);
}

}  // namespace dualhex::testing

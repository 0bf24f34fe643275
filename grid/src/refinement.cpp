#include "dualhex/grid/refinement.hpp"

#include <vector>

#include "octree.hpp"

namespace dualhex {

namespace {

using detail::Octree;

// Balanced (for `mode`) iff every interior node's same-level neighbours through the
// constrained contacts are nodes too (not strictly inside a leaf): the leaves inside an
// interior node P are at level >= level(P)+1 and touch each neighbour of P through the
// same kind of contact. So: visit interior nodes finest level first and split the leaf
// covering each missing neighbour down to that neighbour. Splits create interior nodes
// only at coarser levels, which are visited later; every split is forced, so the result
// is the least balanced refinement. One pass over interior nodes (~1/7 of the leaves).
// `seeds`: the interior nodes that may lack neighbours (all of them, or those just split
// when the rest is known to be balanced).
void balance_tree(Octree& tree, Balance mode, const std::vector<Leaf>& seeds) {
    const auto offsets = neighbour_offsets(mode);
    std::vector<std::vector<Leaf>> by_level(kMaxLevel + 1);
    for (const Leaf& node : seeds) by_level[static_cast<std::size_t>(node.level)].push_back(node);
    for (int level = kMaxLevel; level >= 1; --level) {
        const auto& bucket = by_level[static_cast<std::size_t>(level)];  // only coarser buckets grow
        for (std::size_t n = 0; n < bucket.size(); ++n) {
            for (const Offset& d : offsets) {
                const Leaf cell = neighbour(bucket[n], d);
                if (!cell.valid()) continue;
                for (auto cover = tree.covering_leaf(cell); cover && cover->level < level;
                     cover = tree.covering_leaf(cell)) {
                    tree.split(*cover);
                    by_level[static_cast<std::size_t>(cover->level)].push_back(*cover);
                }
            }
        }
    }
}

// Pairs the tree, given `candidates`: every interior node that may have both leaf and
// interior children. Splitting the leaf children of a mixed node makes that node
// all-interior and creates only all-leaf nodes, so one pass suffices.
void pairing_pass(Octree& tree, const std::vector<Leaf>& candidates) {
    for (const Leaf& node : candidates) {
        const auto kids = children(node);
        bool any_leaf = false, any_interior = false;
        for (const Leaf& c : kids) (tree.is_leaf(c) ? any_leaf : any_interior) = true;
        if (!any_leaf || !any_interior) continue;
        for (const Leaf& c : kids) {
            if (!tree.is_leaf(c)) continue;
            tree.split(c);
        }
    }
}

// A node can become mixed only when one of its children is split.
std::vector<Leaf> parents_of(const std::vector<Leaf>& split) {
    std::vector<Leaf> out;
    out.reserve(split.size());
    for (const Leaf& s : split)
        if (s.level > 0) out.push_back(parent(s));
    return out;
}

}  // namespace

LeafGrid balance(const LeafGrid& grid, Balance mode) {
    Octree tree(grid);
    balance_tree(tree, mode, tree.interior_nodes());
    return tree.to_grid();
}

LeafGrid pair_only(const LeafGrid& grid) {
    Octree tree(grid);
    pairing_pass(tree, tree.interior_nodes());
    return tree.to_grid();
}

// Alternates, each round seeded only with what the previous one changed: nodes split by
// pairing are the only ones that can lack neighbours; parents of nodes split by
// balancing are the only ones that can be mixed.
LeafGrid pair(const LeafGrid& grid, Balance mode) {
    Octree tree(grid);
    balance_tree(tree, mode, tree.interior_nodes());
    (void)tree.take_splits();
    std::vector<Leaf> candidates = tree.interior_nodes();
    for (;;) {
        pairing_pass(tree, candidates);
        const std::vector<Leaf> paired = tree.take_splits();
        if (paired.empty()) break;
        balance_tree(tree, mode, paired);
        candidates = parents_of(tree.take_splits());
    }
    return tree.to_grid();
}

}  // namespace dualhex

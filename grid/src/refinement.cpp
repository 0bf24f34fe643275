#include "dualhex/grid/refinement.hpp"

#include <vector>

#include "octree.hpp"

namespace dualhex {

namespace {

using detail::Octree;

// Ripple balancing seeded with `work`. Each split is forced by a leaf two or more levels
// finer in contact, so no unnecessary refinement is introduced.
void ripple_balance(Octree& tree, std::vector<Leaf> work, Balance mode) {
    const auto offsets = neighbour_offsets(mode);
    while (!work.empty()) {
        const Leaf leaf = work.back();
        work.pop_back();
        if (leaf.level < 2 || !tree.is_leaf(leaf)) continue;  // split since queued: children queued
        for (const Offset& d : offsets) {
            const Leaf cell = neighbour(leaf, d);
            if (!cell.valid()) continue;
            for (auto coarse = tree.covering_leaf(cell); coarse && coarse->level < leaf.level - 1;
                 coarse = tree.covering_leaf(cell)) {
                tree.split(*coarse);
                for (const Leaf& child : children(*coarse)) work.push_back(child);
            }
        }
    }
}

// One pairing pass; returns the new leaves. Splitting the leaf children of a mixed node
// makes that node all-interior and creates only all-leaf nodes, so one pass suffices.
std::vector<Leaf> pairing_pass(Octree& tree) {
    std::vector<Leaf> created;
    for (const Leaf& node : tree.interior_nodes()) {
        const auto kids = children(node);
        bool any_leaf = false, any_interior = false;
        for (const Leaf& c : kids) (tree.is_leaf(c) ? any_leaf : any_interior) = true;
        if (!any_leaf || !any_interior) continue;
        for (const Leaf& c : kids) {
            if (!tree.is_leaf(c)) continue;
            tree.split(c);
            for (const Leaf& g : children(c)) created.push_back(g);
        }
    }
    return created;
}

}  // namespace

LeafGrid balance(const LeafGrid& grid, Balance mode) {
    Octree tree(grid);
    ripple_balance(tree, tree.leaves(), mode);
    return tree.to_grid();
}

LeafGrid pair_only(const LeafGrid& grid) {
    Octree tree(grid);
    pairing_pass(tree);
    return tree.to_grid();
}

LeafGrid pair(const LeafGrid& grid, Balance mode) {
    Octree tree(grid);
    ripple_balance(tree, tree.leaves(), mode);
    // After the first full balance only leaves created by pairing can break balance.
    for (auto created = pairing_pass(tree); !created.empty(); created = pairing_pass(tree))
        ripple_balance(tree, std::move(created), mode);
    return tree.to_grid();
}

}  // namespace dualhex

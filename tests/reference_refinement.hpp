#pragma once
// The reference for the parallel refinements (grid/src/refinement.cpp): the serial
// ripple the grid layer used before them, on a hash map of nodes, kept here as an
// independent oracle. Interior nodes are visited finest level first; the leaf covering a
// missing same-level neighbour is split, the split queued at its coarser level; pairing
// splits the leaf children of every node that has both leaf and interior children; pair()
// alternates the two, each round seeded with the last one's splits. Output sorted by
// (level, i, j, k), as the library's.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "dualhex/grid/cell_map.hpp"
#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/grid/neighbours.hpp"

namespace dualhex::testing::reference {

class Octree {
public:
    explicit Octree(const LeafGrid& grid) : nodes_(2 * grid.size()) {
        for (const Leaf& leaf : grid.leaves()) nodes_.insert(leaf, kLeaf);
        for (const Leaf& leaf : grid.leaves())
            for (int level = leaf.level - 1; level >= 0; --level)
                if (!nodes_.insert(ancestor(leaf, level), kInterior).second) break;
    }
    [[nodiscard]] bool is_leaf(const Leaf& cell) const {
        const auto* v = nodes_.find(cell);
        return v != nullptr && *v == kLeaf;
    }
    [[nodiscard]] std::optional<Leaf> covering_leaf(const Leaf& cell) const {
        for (int level = cell.level; level >= 0; --level) {
            const Leaf up = ancestor(cell, level);
            if (const auto* v = nodes_.find(up)) return *v == kLeaf ? std::optional<Leaf>(up) : std::nullopt;
        }
        return std::nullopt;
    }
    void split(const Leaf& leaf) {
        *nodes_.find(leaf) = kInterior;
        for (const Leaf& child : children(leaf)) nodes_.insert(child, kLeaf);
        splits_.push_back(leaf);
    }
    [[nodiscard]] std::vector<Leaf> take_splits() { return std::exchange(splits_, {}); }
    [[nodiscard]] std::vector<Leaf> nodes(std::uint8_t kind) const {
        std::vector<Leaf> out;
        nodes_.for_each([&](const Leaf& cell, std::uint8_t v) {
            if (v == kind) out.push_back(cell);
        });
        return out;
    }
    [[nodiscard]] LeafGrid to_grid() const {
        std::vector<Leaf> out = nodes(kLeaf);
        std::sort(out.begin(), out.end());
        return LeafGrid(std::move(out));
    }
    static constexpr std::uint8_t kLeaf = 1, kInterior = 2;

private:
    CellMap<std::uint8_t> nodes_;
    std::vector<Leaf> splits_;
};

inline void balance_tree(Octree& tree, Balance mode, const std::vector<Leaf>& seeds) {
    std::vector<std::vector<Leaf>> by_level(kMaxLevel + 1);
    for (const Leaf& node : seeds) by_level[static_cast<std::size_t>(node.level)].push_back(node);
    for (int level = kMaxLevel; level >= 1; --level) {
        const auto& bucket = by_level[static_cast<std::size_t>(level)];
        for (std::size_t n = 0; n < bucket.size(); ++n)
            for (const Offset& d : neighbour_offsets(mode)) {
                const Leaf cell = neighbour(bucket[n], d);
                if (!cell.valid()) continue;
                for (auto cover = tree.covering_leaf(cell); cover && cover->level < level; cover = tree.covering_leaf(cell)) {
                    tree.split(*cover);
                    by_level[static_cast<std::size_t>(cover->level)].push_back(*cover);
                }
            }
    }
}

inline void pairing_pass(Octree& tree, const std::vector<Leaf>& candidates) {
    for (const Leaf& node : candidates) {
        bool any_leaf = false, any_interior = false;
        for (const Leaf& c : children(node)) (tree.is_leaf(c) ? any_leaf : any_interior) = true;
        if (!any_leaf || !any_interior) continue;
        for (const Leaf& c : children(node))
            if (tree.is_leaf(c)) tree.split(c);
    }
}

inline LeafGrid balance(const LeafGrid& grid, Balance mode) {
    Octree tree(grid);
    balance_tree(tree, mode, tree.nodes(Octree::kInterior));
    return tree.to_grid();
}

inline LeafGrid pair_only(const LeafGrid& grid) {
    Octree tree(grid);
    pairing_pass(tree, tree.nodes(Octree::kInterior));
    return tree.to_grid();
}

inline LeafGrid pair(const LeafGrid& grid, Balance mode) {
    Octree tree(grid);
    balance_tree(tree, mode, tree.nodes(Octree::kInterior));
    (void)tree.take_splits();
    std::vector<Leaf> candidates = tree.nodes(Octree::kInterior);
    for (;;) {
        pairing_pass(tree, candidates);
        const std::vector<Leaf> paired = tree.take_splits();
        if (paired.empty()) break;
        balance_tree(tree, mode, paired);
        candidates.clear();
        for (const Leaf& s : tree.take_splits())
            if (s.level > 0) candidates.push_back(parent(s));
    }
    return tree.to_grid();
}

}  // namespace dualhex::testing::reference

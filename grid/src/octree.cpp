#include "octree.hpp"

#include <algorithm>

namespace dualhex::detail {

Octree::Octree(const LeafGrid& grid) : nodes_(2 * grid.size()), leaf_count_(grid.size()) {
    for (const Leaf& leaf : grid.leaves()) nodes_.insert(leaf, kLeaf);
    for (const Leaf& leaf : grid.leaves())
        for (int level = leaf.level - 1; level >= 0; --level)
            if (!nodes_.insert(ancestor(leaf, level), kInterior).second) break;
}

bool Octree::is_leaf(const Leaf& cell) const {
    const auto* v = nodes_.find(cell);
    return v != nullptr && *v == kLeaf;
}

std::optional<Leaf> Octree::covering_leaf(const Leaf& cell) const {
    for (int level = cell.level; level >= 0; --level) {
        const Leaf up = ancestor(cell, level);
        if (const auto* v = nodes_.find(up)) {
            if (*v == kLeaf) return up;
            return std::nullopt;
        }
    }
    return std::nullopt;
}

void Octree::split(const Leaf& leaf) {
    *nodes_.find(leaf) = kInterior;
    for (const Leaf& child : children(leaf)) nodes_.insert(child, kLeaf);
    leaf_count_ += 7;
    splits_.push_back(leaf);
}

std::vector<Leaf> Octree::leaves() const {
    std::vector<Leaf> out;
    out.reserve(leaf_count_);
    nodes_.for_each([&](const Leaf& cell, std::uint8_t v) {
        if (v == kLeaf) out.push_back(cell);
    });
    return out;
}

std::vector<Leaf> Octree::interior_nodes() const {
    std::vector<Leaf> out;
    nodes_.for_each([&](const Leaf& cell, std::uint8_t v) {
        if (v == kInterior) out.push_back(cell);
    });
    return out;
}

LeafGrid Octree::to_grid() const {
    std::vector<Leaf> out = leaves();
    std::sort(out.begin(), out.end());
    return LeafGrid(std::move(out));
}

}  // namespace dualhex::detail

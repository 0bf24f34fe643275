#pragma once
// A mutable octree for refinement algorithms (private to the grid layer): every node is
// a leaf or interior, stored in one flat hash map. Refinement only ever turns a leaf into
// an interior node with 8 new leaves, so nothing is erased.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "dualhex/grid/cell_map.hpp"
#include "dualhex/grid/leaf_grid.hpp"

namespace dualhex::detail {

class Octree {
public:
    explicit Octree(const LeafGrid& grid);

    [[nodiscard]] bool is_leaf(const Leaf& cell) const;
    /// The leaf containing `cell` (equal or coarser); empty if `cell` is subdivided.
    [[nodiscard]] std::optional<Leaf> covering_leaf(const Leaf& cell) const;
    /// Turns leaf `leaf` into an interior node with 8 leaf children (logged).
    void split(const Leaf& leaf);
    /// The leaves split since the last call, in order; clears the log.
    [[nodiscard]] std::vector<Leaf> take_splits() { return std::exchange(splits_, {}); }

    [[nodiscard]] std::vector<Leaf> leaves() const;
    [[nodiscard]] std::vector<Leaf> interior_nodes() const;
    [[nodiscard]] std::size_t leaf_count() const { return leaf_count_; }
    /// The leaves sorted by (level, i, j, k), as a validated LeafGrid.
    [[nodiscard]] LeafGrid to_grid() const;

private:
    enum : std::uint8_t { kLeaf = 1, kInterior = 2 };
    CellMap<std::uint8_t> nodes_;
    std::size_t leaf_count_ = 0;
    std::vector<Leaf> splits_;
};

}  // namespace dualhex::detail

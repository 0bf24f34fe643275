#pragma once
// LeafGrid: the leaves of an octree that tiles the root cube exactly, with O(1) lookup of
// a leaf by (level,i,j,k) and point location (which leaf contains a given cell).
//
// Construction validates everything and throws InputError naming the offending leaves
// (and their source lines when the grid came from a file): a leaf out of range, a
// duplicate, an overlap (one leaf inside another) or a gap (a cell no leaf covers).
// So a LeafGrid that exists is always a valid tiling.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dualhex/grid/cell_map.hpp"
#include "dualhex/grid/leaf.hpp"

namespace dualhex {

class LeafGrid {
public:
    /// The root cube as a single leaf.
    LeafGrid();
    /// `source` names the file (may be empty); `lines[n]` is leaf n's 1-based line in it
    /// (empty vector: no line information). Throws InputError unless the leaves tile.
    explicit LeafGrid(std::vector<Leaf> leaves, std::string source = {}, std::vector<int> lines = {});

    [[nodiscard]] std::size_t size() const { return leaves_.size(); }
    [[nodiscard]] const std::vector<Leaf>& leaves() const { return leaves_; }
    [[nodiscard]] const Leaf& leaf(std::size_t n) const { return leaves_[n]; }
    /// 1-based source line of leaf n, 0 if unknown.
    [[nodiscard]] int line(std::size_t n) const { return lines_.empty() ? 0 : lines_[n]; }
    [[nodiscard]] const std::string& source() const { return source_; }

    /// Index of the leaf equal to `cell`, if it is one.
    [[nodiscard]] std::optional<std::size_t> find(const Leaf& cell) const;
    /// True iff `cell` is a proper ancestor of some leaf (an interior node of the octree).
    [[nodiscard]] bool is_subdivided(const Leaf& cell) const;
    /// Point location: the leaf that contains `cell` (equal or coarser). Empty if `cell`
    /// is subdivided into finer leaves or lies outside the root cube.
    [[nodiscard]] std::optional<std::size_t> locate(const Leaf& cell) const;
    /// Some leaf inside or equal to `cell` (used to name a witness), empty if outside.
    [[nodiscard]] std::optional<std::size_t> leaf_within(const Leaf& cell) const;

    /// The interior nodes of the octree (proper ancestors of leaves), unspecified order.
    [[nodiscard]] std::vector<Leaf> interior_nodes() const;

    /// counts[L] = number of leaves at level L, for L = 0..max_level().
    [[nodiscard]] std::vector<std::size_t> counts_per_level() const;
    [[nodiscard]] int min_level() const;
    [[nodiscard]] int max_level() const;
    /// "L i j k" plus " (line N)" when known: how diagnostics name a leaf.
    [[nodiscard]] std::string describe(std::size_t n) const;

private:
    void index_leaves();
    void index_ancestors();
    void find_gap() const;

    std::vector<Leaf> leaves_;
    std::vector<int> lines_;
    std::string source_;
    // leaf -> its index (>= 0); interior node -> -1 - (index of some leaf below it).
    CellMap<std::int32_t> nodes_;
};

}  // namespace dualhex

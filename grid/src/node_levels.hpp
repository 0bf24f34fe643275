#pragma once
// The interior nodes of an octree as one sorted array per level (private to the grid
// layer): the representation of the parallel refinements (refinement.cpp). A cell of one
// level is a 128-bit key (i, j, k lexicographic), so sorting a level orders its cells as
// Leaf's (level, i, j, k) order does, and a sorted unique array is a set whatever the
// order its cells were found in: building it in parallel gives the same array for any
// number of threads.
#include <cstdint>
#include <vector>

#include "dualhex/grid/leaf_grid.hpp"

namespace dualhex::detail {

__extension__ typedef unsigned __int128 CellKey128;  // GCC and Clang

[[nodiscard]] inline CellKey128 key_of(const Leaf& c) {
    return static_cast<CellKey128>(c.i) << 60 | static_cast<CellKey128>(c.j) << 30 | static_cast<CellKey128>(c.k);
}

[[nodiscard]] inline Leaf cell_of(int level, CellKey128 key) {
    constexpr CellKey128 low30 = (CellKey128{1} << 30) - 1;
    return {level, static_cast<std::int64_t>(key >> 60), static_cast<std::int64_t>(key >> 30 & low30),
            static_cast<std::int64_t>(key & low30)};
}

/// Sorts `keys` and drops repeats (oneTBB parallel sort; equal keys are identical).
void sort_unique(std::vector<CellKey128>& keys);

class NodeLevels {
public:
    /// The interior nodes of `grid`: the parents of its leaves (their ancestors follow by
    /// the refinement's parent rule), one level per entry.
    explicit NodeLevels(const LeafGrid& grid);

    [[nodiscard]] int deepest() const { return static_cast<int>(levels_.size()) - 1; }
    [[nodiscard]] std::vector<CellKey128>& level(int l) { return levels_[static_cast<std::size_t>(l)]; }
    /// Adds `keys` (any order, repeats allowed) to level `l`; the level stays sorted, unique.
    void add(int l, std::vector<CellKey128> keys);

    /// The leaves of the octree these interior nodes define (every child of a node that is
    /// not a node; the root alone if there is none), sorted by (level, i, j, k).
    [[nodiscard]] std::vector<Leaf> leaves() const;

private:
    std::vector<std::vector<CellKey128>> levels_;  // [level] sorted unique
};

}  // namespace dualhex::detail

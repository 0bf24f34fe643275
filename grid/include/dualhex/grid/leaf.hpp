#pragma once
// A leaf of an octree over the root cube [0,1]^3: level L, integer position (i,j,k),
// covering [i,i+1]x[j,j+1]x[k,k+1] * 2^-L. Valid iff 0 <= L <= kMaxLevel and
// 0 <= i,j,k < 2^L. The same struct names any octree node ("cell"), leaf or not.
#include <array>
#include <compare>
#include <cstdint>
#include <string>

#include "dualhex/topology/lattice.hpp"

namespace dualhex {

/// Deepest level accepted anywhere (files, operations). At level <= 30 every coordinate
/// is below 2^30: a cell packs into 128 bits (see cell_map.hpp) and a box at the finest
/// level has coordinates <= 2^30, far from int64 overflow. Octree meshing never gets near.
inline constexpr int kMaxLevel = 30;

struct Leaf {
    int level = 0;
    std::int64_t i = 0, j = 0, k = 0;

    constexpr auto operator<=>(const Leaf&) const = default;

    [[nodiscard]] constexpr std::int64_t coord(int axis) const { return axis == 0 ? i : axis == 1 ? j : k; }
    /// Number of cells per axis at this level (2^level).
    [[nodiscard]] constexpr std::int64_t extent() const { return std::int64_t{1} << level; }
    /// True iff the level is in [0, kMaxLevel] and the position inside the root cube.
    [[nodiscard]] bool valid() const;
};

/// Axis-aligned integer box [lo, hi) at some level (coordinates in cells of that level).
struct LeafBox {
    LatticePoint lo, hi;
    int level = 0;
};

/// The node one level up. Precondition: level > 0.
[[nodiscard]] Leaf parent(const Leaf& leaf);
/// The ancestor at `level` (<= leaf.level).
[[nodiscard]] Leaf ancestor(const Leaf& leaf, int level);
/// The 8 children, child c has offsets (c&1, c>>1&1, c>>2&1).
[[nodiscard]] std::array<Leaf, 8> children(const Leaf& leaf);
/// Child index (0..7) of this node within its parent. Precondition: level > 0.
[[nodiscard]] int child_index(const Leaf& leaf);
/// The leaf as a box of cells at a finer (or equal) level. Precondition: level >= leaf.level.
[[nodiscard]] LeafBox box_at(const Leaf& leaf, int level);
/// True iff `outer` contains `inner` (or they are equal).
[[nodiscard]] bool contains(const Leaf& outer, const Leaf& inner);
/// "L i j k", the leaf-file form.
[[nodiscard]] std::string to_string(const Leaf& leaf);

}  // namespace dualhex

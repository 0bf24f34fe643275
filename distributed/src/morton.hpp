#pragma once
// Morton positions of cells at p8est's finest level (18 bits per axis, x lowest: the
// order of p8est_quadrant_linear_id), so a cell is the position range
// [position, position + volume(level)) and sorting by (position, level) puts a cell
// before everything inside it.
#include <cstdint>

#include "dualhex/grid/leaf.hpp"
#include "forest.hpp"

namespace dualhex::dist {

inline constexpr int kMortonLevel = kForestMaxLevel;

/// Positions a cell of `level` spans: 8^(18 - level).
[[nodiscard]] inline std::uint64_t morton_volume(int level) { return std::uint64_t{1} << (3 * (kMortonLevel - level)); }

/// The position of the cell's first finest-level descendant (level <= 18).
[[nodiscard]] inline std::uint64_t morton_position(const Leaf& cell) {
    const int shift = kMortonLevel - cell.level;
    const auto x = static_cast<std::uint64_t>(cell.i) << shift, y = static_cast<std::uint64_t>(cell.j) << shift,
               z = static_cast<std::uint64_t>(cell.k) << shift;
    std::uint64_t p = 0;
    for (int b = 0; b < kMortonLevel; ++b)
        p |= ((x >> b) & 1U) << (3 * b) | ((y >> b) & 1U) << (3 * b + 1) | ((z >> b) & 1U) << (3 * b + 2);
    return p;
}

/// The cell of `level` that starts at `position` (which must be aligned to its volume).
[[nodiscard]] inline Leaf morton_cell(std::uint64_t position, int level) {
    std::int64_t c[3] = {0, 0, 0};
    for (int b = 0; b < kMortonLevel; ++b)
        for (int a = 0; a < 3; ++a) c[a] |= static_cast<std::int64_t>((position >> (3 * b + a)) & 1U) << b;
    const int shift = kMortonLevel - level;
    return {level, c[0] >> shift, c[1] >> shift, c[2] >> shift};
}

}  // namespace dualhex::dist

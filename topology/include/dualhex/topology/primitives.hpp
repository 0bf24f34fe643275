#pragma once
// Small reference complexes: axis-aligned cubes and boxes of cubes, outward-oriented.
#include <array>
#include <cstdint>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"

namespace dualhex {

/// The 6 faces of the cube [corner, corner + size]^3 as vertex loops, each
/// counter-clockwise seen from outside (outward right-hand normal).
[[nodiscard]] std::vector<std::vector<LatticePoint>> cube_loops(const LatticePoint& corner, std::int64_t size = 1);

/// A box of counts[0] x counts[1] x counts[2] cubes of edge `size`, lower corner `origin`.
/// Throws std::invalid_argument for a non-positive count or size.
[[nodiscard]] CellComplex make_box(const LatticePoint& origin, std::array<int, 3> counts, std::int64_t size = 1);

}  // namespace dualhex

#pragma once
// Moving a grid by one of the 48 cube symmetries, about the centre of the root cube.
#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/topology/cube_symmetry.hpp"

namespace dualhex {

/// The image of one leaf: its box [lo, lo+1] at its own level, mapped about the centre
/// of [0, 2^level]^3, is again a leaf box of that level.
[[nodiscard]] Leaf apply(const CubeSymmetry& s, const Leaf& leaf);

/// Every leaf moved by `s`; leaf n of the result is the image of leaf n (same source line).
[[nodiscard]] LeafGrid apply(const CubeSymmetry& s, const LeafGrid& grid);

}  // namespace dualhex

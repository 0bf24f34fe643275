#pragma once
// The octree level of each hex of the clipped dual, for the output's cell data.
//
// Hex h of the clipped dual is the dual of the primal vertex dual.primal_vertex[h]. Its
// level is the finest (largest) level among the grid leaves whose closed cube contains
// that vertex: for a vertex inside a leaf's element, that leaf's level; for a vertex on
// leaf corners, edges or faces, the finest leaf around it, because the hex's size is set
// by its smallest neighbouring cells. Exact: lattice positions, integer division.
#include <cstdint>
#include <vector>

#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/install.hpp"
#include "dualhex/topology/clipped_dual.hpp"

namespace dualhex::mesher {

/// One level per hex of `dual` (the clipped dual of `installed`, which was built from `grid`).
[[nodiscard]] std::vector<int> dual_hex_levels(const ClippedDual& dual, const InstallResult& installed,
                                               const LeafGrid& grid);

}  // namespace dualhex::mesher

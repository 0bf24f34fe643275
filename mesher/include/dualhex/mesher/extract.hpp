#pragma once
// Stage "extract": embed the clipped dual in space and keep the hexes inside the surface.
#include <cstdint>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/topology/clipped_dual.hpp"

namespace dualhex::mesher {

/// Input: the clipped dual over the lattice cube [0, extent]^3, the root cube it maps to
/// (lattice point p -> root.origin + root.size * p / extent; a dual vertex is its rational
/// centroid, mapped), the surface's tree. Output: the hexes whose centroid is inside the
/// surface (is_inside), VTK order, points renumbered in first-use order. May be empty.
[[nodiscard]] geometry::HexMesh extract_inside(const ClippedDual& dual, std::int64_t extent,
                                               const geometry::RootCube& root, const geometry::AabbTree& tree);

}  // namespace dualhex::mesher

#pragma once
// The forest of a surface: p8est_refine with the serial surface octree's criterion
// (geometry::SurfaceRefinement, geometry/surface_octree.hpp) as the refine callback, one
// level per round with a repartition after each, so the refinement is spread over the
// ranks. Every rank holds the whole surface and its AABB tree (small next to the forest).
//
// The criterion of a cell depends on its parent's near triangles, which the serial
// recursion hands down; here each rank keeps the chain of near lists from the root to the
// quadrant it is deciding (NearChain), recomputed from the root for the ancestors it has
// not seen (after a repartition), so every cell gets the very triangle list, and so the
// very decision, of the serial octree: the same leaves, on any number of ranks.
// A decided leaf is marked (the quadrant's int) and not asked again.
//
// Leaf budget: after each round the global leaf count is checked against max_leaves
// (OctreeTooLarge on every rank); the serial octree stops at a slightly different point
// of its depth-first walk, so near the limit one may refuse what the other accepts.
#include <cstddef>
#include <cstdint>

#include "dualhex/geometry/surface_octree.hpp"
#include "forest.hpp"

namespace dualhex::dist {

struct SurfaceForestStats {
    int rounds = 0;
    std::int64_t octree_leaves = 0;     ///< global, before balance and pairing
    std::int64_t crossing_leaves = 0;   ///< global: leaves the surface crosses
    std::int64_t curvature_splits = 0;  ///< global: cells split by curvature alone
    std::uint64_t decisions = 0, ancestor_recomputations = 0;  ///< by this rank
};

/// Collective. `forest` must be the level-0 forest (Forest(comm, 0)).
SurfaceForestStats refine_to_surface(Forest& forest, const geometry::SurfaceRefinement& criterion);

}  // namespace dualhex::dist

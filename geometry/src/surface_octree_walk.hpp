#pragma once
// The walk that builds surface_octree's leaves from its refinement criterion (private to
// the geometry layer): depth first, children in child-index order, so the leaves come out
// in Morton order, the order of the serial recursion.
#include <cstddef>
#include <vector>

#include "dualhex/geometry/surface_octree.hpp"

namespace dualhex::geometry::detail {

struct WalkResult {
    std::vector<Leaf> leaves;  ///< depth-first (Morton) order
    std::size_t crossing = 0, curvature_splits = 0;
};

/// The serial recursion with the leaf budget: throws OctreeTooLarge at the first split (in
/// depth-first order) after which more than max_leaves leaves would have been emitted.
[[nodiscard]] WalkResult serial_walk(const SurfaceRefinement& criterion);

/// The same result as serial_walk, bit for bit, for any number of threads (oneTBB): the
/// subtrees of the cells above kParallelLevels are walked in parallel and concatenated in
/// child order. Past the budget it gives up and runs serial_walk, which throws exactly as
/// it always did (or, near the limit, returns the octree the serial budget accepts).
[[nodiscard]] WalkResult parallel_walk(const SurfaceRefinement& criterion);

/// Cells above this level hand their 8 children to parallel tasks (at most 8^4 tasks).
inline constexpr int kParallelLevels = 4;

}  // namespace dualhex::geometry::detail

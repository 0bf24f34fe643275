#pragma once
// Stage "refine": local octree refinement where the first core does not resolve the
// surface (issue 12: Hausdorff, thin parts).
//
// At thin parts (ears, plates, necks) the octree at the target size can be too coarse for
// the rule's core: the dual hexes there have corners outside, the selection gets tunnels,
// the topology-controlled regrowth cuts, and the pad then bridges from coarse interior
// faces to the surface (quads several target sizes away from it), and rays of the pad can
// land on the wrong sheet of a thin part. Such a place shows when the core is padded: there
// the padded mesh's boundary and the input are far apart, elsewhere within a fraction of a
// cell (the pipeline pads a copy of each core to look: the pad stage's own work).
//
// Unresolved places: samples of the input (vertices, triangle centroids) farther than
// `far` from a hex mesh's boundary (the padded core), and samples of that boundary (the
// same) farther than `far` from the input, placed at their closest input point (where the
// mesh should have been); farthest first, one per ball of its distance (a sample inside a
// listed place's ball is part of it). Refinement: every octree leaf that meets a place's
// ball (radius: its distance, at most `far`: a local repair, not a region's) and is at
// most as deep as the leaf containing the place's point is split once (below max_depth). The pipeline then re-balances, re-pairs, re-installs and
// re-selects the core (its own stages) and repeats for at most `rounds` rounds, stopping
// early when no place is left or no leaf was split, or before a round that would exceed
// max_leaves. Deterministic: samples in input order, ties kept by a stable sort.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/grid/leaf_grid.hpp"

namespace dualhex::mesher {

struct UnresolvedPlace {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< a point of the input surface
    double distance = 0;                                ///< between the input and the mesh's boundary there
};

/// Input: a hex mesh (its boundary quads; the pipeline's padded core), the input surface's
/// tree, the distance above which a sample is far (absolute). Output: the places, farthest
/// first. An empty mesh resolves nothing: then every input sample is unresolved, its
/// distance `far`.
[[nodiscard]] std::vector<UnresolvedPlace> unresolved_places(const geometry::HexMesh& core,
                                                             const geometry::AabbTree& surface, double far);

struct LocalRefinement {
    LeafGrid grid;           ///< the octree with the leaves split (unbalanced, like its input)
    std::size_t split = 0;   ///< leaves split (each becomes 8)
};

/// Splits, once, every leaf of `octree` (embedded by `root`) that meets some place's ball
/// (radius: its distance, at most max_radius) and is at most as deep as the leaf
/// containing the place's point, if below max_depth.
[[nodiscard]] LocalRefinement refine_at_places(const LeafGrid& octree, const geometry::RootCube& root,
                                               const std::vector<UnresolvedPlace>& places, int max_depth,
                                               double max_radius);

}  // namespace dualhex::mesher

#pragma once
// Stage "report": the figures of a finished hex mesh that the pipeline reports.
#include <array>
#include <cstddef>
#include <map>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/core_selection.hpp"

namespace dualhex::mesher {

/// Interior edges (not an edge of a boundary quad) with a number of hexes != 4:
/// valence -> count.
[[nodiscard]] std::map<int, std::size_t> interior_singular_edge_valences(const geometry::HexMesh& mesh);

/// A place where the input surface is far from the hex boundary, and why (the diagnostic
/// behind the Hausdorff distance): the dual hexes whose centroid lies within `distance` of
/// the point (of its closest input point for a hex-boundary point) and inside the surface,
/// counted by what the core stage decided about them.
/// cause: the most frequent of the decisions that left inside hexes out (Cut, DroppedPart,
/// RepairOut, Thin), or Core if every such hex is in the core (then the pad's shape, not
/// the core, is far from the surface).
struct FarSurfacePoint {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    bool on_hex_boundary = false;  ///< a point of the hex boundary far from the input (else of the input)
    double distance = 0;  ///< to the other side (absolute)
    std::array<std::size_t, kCoreFates> fates{};
    CoreFate cause = CoreFate::Core;
};

/// Input: the finished mesh, the input surface's tree, the core stage's fates and dual
/// centroids (CoreSelection::fate, dual_centroid), the distance above which a surface point
/// is far (absolute) and the most places to return.
/// Output: up to max_points places per direction, farthest first (input side first, then
/// the hex boundary's); samples are the vertices and triangle (quad) centroids of each
/// side, distances exact (point to the other side's triangles, AabbTree), and a sample
/// within the distance of a place already listed is part of that place.
[[nodiscard]] std::vector<FarSurfacePoint> far_surface_points(const geometry::HexMesh& mesh,
                                                              const geometry::AabbTree& surface,
                                                              const CoreSelection& core, double far,
                                                              std::size_t max_points = 8);

}  // namespace dualhex::mesher

#pragma once
// Internal to the mesher: where two surfaces are far apart, sampled (the report's
// far_surface_points and the refine stage's unresolved places share it).
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/surface.hpp"

namespace dualhex::mesher::detail {

/// The sample points of a triangle surface: its used vertices (in id order), then its
/// triangles' centroids (in triangle order).
[[nodiscard]] std::vector<Eigen::Vector3d> surface_samples(const geometry::TriangleSurface& surface);

struct FarSample {
    double distance;
    Eigen::Vector3d point, closest;  ///< the sample, its closest point on the other surface
};

/// The samples of `from` farther than `far` from `to`, farthest first (ties in sample order).
[[nodiscard]] std::vector<FarSample> far_samples(const geometry::TriangleSurface& from, const geometry::AabbTree& to,
                                                 double far);

}  // namespace dualhex::mesher::detail

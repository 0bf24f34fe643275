#pragma once
// Internal (features.cpp): when a feature path may not take two edges of one boundary quad.
#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/feature_curves.hpp"

namespace dualhex::mesher::detail {

/// For a path p -> u -> v whose two edges lie in one boundary quad: whether `line` (open)
/// runs straight there, i.e. the closest points of p and v, seen from u's, turn by less
/// than 45 degrees (or coincide with it). Moved onto the line, the three corners would be
/// nearly collinear and the quad a triangle (its pad hex flat); where the line itself turns
/// the quad keeps an angle.
[[nodiscard]] inline bool straight_on_line(const Eigen::Vector3d& p, const Eigen::Vector3d& u,
                                           const Eigen::Vector3d& v, const std::vector<Eigen::Vector3d>& line) {
    const Eigen::Vector3d cu = geometry::closest_on_polyline(line, false, u).point;
    const Eigen::Vector3d back = geometry::closest_on_polyline(line, false, p).point - cu;
    const Eigen::Vector3d ahead = geometry::closest_on_polyline(line, false, v).point - cu;
    const double norms = back.norm() * ahead.norm();
    return !(norms > 0) || back.dot(ahead) < -std::cos(std::numbers::pi / 4) * norms;
}

}  // namespace dualhex::mesher::detail

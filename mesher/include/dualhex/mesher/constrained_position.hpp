#pragma once
// Where a vertex may go under its role (vertex_constraints.hpp), for the stages that move
// vertices (smooth, optimise):
//   Interior — anywhere;
//   Surface  — onto the input surface: a move is taken in the tangent plane of the closest
//              surface point, then the result is re-projected onto its closest point;
//   Curve    — onto its feature curve: FeatureCurves[curve] is a polyline (assumed: the
//              points in order, closed iff the first equals the last; at least 2 points),
//              moves are taken along the tangent of the nearest segment and re-projected
//              onto the closest polyline point;
//   Corner   — never moves.
// Input : the surface tree, the polylines, the roles (points). Errors: std::invalid_argument
//         from check_constraints for a role vector of the wrong size or a Curve vertex whose
//         curve index is not a polyline of >= 2 points.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/mesher/vertex_constraints.hpp"

namespace dualhex::mesher {

/// Feature curves as polylines (curve c: its points in order).
using FeatureCurves = std::vector<std::vector<Eigen::Vector3d>>;

struct VertexDomain {
    const geometry::AabbTree& surface;
    const FeatureCurves& curves;
    const VertexConstraints& constraints;

    [[nodiscard]] VertexRole role(std::size_t v) const { return constraints.role[v]; }
    /// `candidate` moved onto v's domain (Corner: `current`).
    [[nodiscard]] Eigen::Vector3d project(std::size_t v, const Eigen::Vector3d& candidate,
                                          const Eigen::Vector3d& current) const;
    /// `direction` restricted to v's domain at `at` (tangent plane, curve tangent, zero).
    [[nodiscard]] Eigen::Vector3d restrict(std::size_t v, const Eigen::Vector3d& at, const Eigen::Vector3d& direction) const;
};

/// Throws std::invalid_argument naming the vertex if the constraints do not fit.
void check_constraints(const VertexConstraints& constraints, std::size_t points, const FeatureCurves& curves);

/// The closest point of a polyline to p, and the unit direction of its segment.
struct PolylinePoint {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
};
[[nodiscard]] PolylinePoint closest_on_polyline(const std::vector<Eigen::Vector3d>& polyline, const Eigen::Vector3d& p);

}  // namespace dualhex::mesher

#pragma once
// Single-triangle predicates and queries used by the AABB tree (doubles, no epsilon
// except where stated).
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dualhex::geometry {

/// The point of triangle (a,b,c) closest to p (Ericson, Real-Time Collision Detection 5.1.5).
[[nodiscard]] Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                                        const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// True iff the closed triangle and the closed box share a point (separating axis test,
/// Akenine-Moeller 2001: 3 box axes, the triangle normal, 9 edge cross products).
[[nodiscard]] bool triangle_box_overlap(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& a,
                                        const Eigen::Vector3d& b, const Eigen::Vector3d& c);

struct RayTriangleHit {
    double t = 0;     ///< origin + t * direction is the hit point
    double u = 0, v = 0;  ///< barycentric: point = (1-u-v) a + u b + v c
};

/// Moeller-Trumbore: the hit of the ray origin + t*dir (t > t_min) with the closed
/// triangle; none for a ray parallel to the triangle's plane (|det| < 1e-300 relative).
[[nodiscard]] std::optional<RayTriangleHit> ray_triangle(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                                         const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                         const Eigen::Vector3d& c, double t_min = 0.0);

/// Solid angle of triangle (a,b,c) seen from p, signed (van Oosterom & Strackee 1983);
/// sums to 4*pi (times the winding number) over a closed outward surface.
[[nodiscard]] double solid_angle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 const Eigen::Vector3d& c);

}  // namespace dualhex::geometry

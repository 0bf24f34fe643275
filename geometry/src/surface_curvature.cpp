// Normal spread of a set of triangles (surface_curvature.hpp).
#include "dualhex/geometry/surface_curvature.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dualhex::geometry {

std::vector<Eigen::Vector3d> area_normals(const TriangleSurface& surface) {
    std::vector<Eigen::Vector3d> out;
    out.reserve(surface.triangles.size());
    for (const auto& t : surface.triangles) {
        const Eigen::Vector3d& a = surface.vertices[t[0]];
        out.push_back(0.5 * (surface.vertices[t[1]] - a).cross(surface.vertices[t[2]] - a));
    }
    return out;
}

double surface_area(const TriangleSurface& surface) {
    double area = 0;
    for (const Eigen::Vector3d& n : area_normals(surface)) area += n.norm();
    return area;
}

double normal_spread(const std::vector<int>& tris, const std::vector<Eigen::Vector3d>& area_normals) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double area = 0;
    for (int t : tris) {
        sum += area_normals[t];
        area += area_normals[t].norm();
    }
    if (!(area > 0)) return 0.0;
    // Opposite sheets (or a closed piece) inside the region: no meaningful mean direction.
    if (sum.norm() <= 1e-6 * area) return std::numbers::pi;
    const Eigen::Vector3d mean = sum.normalized();
    double min_cos = 1.0;
    for (int t : tris) {
        const double a = area_normals[t].norm();
        if (a > 0) min_cos = std::min(min_cos, area_normals[t].dot(mean) / a);
    }
    return std::acos(std::clamp(min_cos, -1.0, 1.0));
}

}  // namespace dualhex::geometry

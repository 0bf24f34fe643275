// Vertex domains under roles (constrained_position.hpp).
#include "dualhex/mesher/constrained_position.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace dualhex::mesher {

PolylinePoint closest_on_polyline(const std::vector<Eigen::Vector3d>& polyline, const Eigen::Vector3d& p) {
    PolylinePoint best;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
        const Eigen::Vector3d a = polyline[i], ab = polyline[i + 1] - a;
        const double len2 = ab.squaredNorm();
        if (len2 == 0) continue;
        const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
        const Eigen::Vector3d q = a + t * ab;
        const double d = (q - p).squaredNorm();
        if (d < best_d) {
            best_d = d;
            best = {q, ab / std::sqrt(len2)};
        }
    }
    return best;
}

Eigen::Vector3d VertexDomain::project(std::size_t v, const Eigen::Vector3d& candidate,
                                      const Eigen::Vector3d& current) const {
    switch (role(v)) {
        case VertexRole::Interior: return candidate;
        case VertexRole::Surface: return surface.closest_point(candidate).point;
        case VertexRole::Curve:
            return closest_on_polyline(curves[static_cast<std::size_t>(constraints.curve[v])], candidate).point;
        case VertexRole::Corner: return current;
    }
    return current;
}

Eigen::Vector3d VertexDomain::restrict(std::size_t v, const Eigen::Vector3d& at, const Eigen::Vector3d& d) const {
    switch (role(v)) {
        case VertexRole::Interior: return d;
        case VertexRole::Surface: {
            const geometry::ClosestPoint c = surface.closest_point(at);
            const auto& tri = surface.surface().triangles[static_cast<std::size_t>(c.triangle)];
            const auto& x = surface.surface().vertices;
            Eigen::Vector3d n = (x[static_cast<std::size_t>(tri[1])] - x[static_cast<std::size_t>(tri[0])])
                                    .cross(x[static_cast<std::size_t>(tri[2])] - x[static_cast<std::size_t>(tri[0])]);
            if (n.squaredNorm() == 0) return Eigen::Vector3d::Zero();
            n.normalize();
            return d - d.dot(n) * n;
        }
        case VertexRole::Curve: {
            const Eigen::Vector3d t =
                closest_on_polyline(curves[static_cast<std::size_t>(constraints.curve[v])], at).tangent;
            return d.dot(t) * t;
        }
        case VertexRole::Corner: return Eigen::Vector3d::Zero();
    }
    return Eigen::Vector3d::Zero();
}

void check_constraints(const VertexConstraints& c, std::size_t points, const FeatureCurves& curves) {
    if (c.role.size() != points || c.curve.size() != points)
        throw std::invalid_argument("vertex constraints: " + std::to_string(c.role.size()) + " roles for " +
                                    std::to_string(points) + " points");
    for (std::size_t v = 0; v < points; ++v) {
        if (c.role[v] != VertexRole::Curve) continue;
        const std::int32_t k = c.curve[v];
        if (k < 0 || static_cast<std::size_t>(k) >= curves.size() || curves[static_cast<std::size_t>(k)].size() < 2)
            throw std::invalid_argument("vertex constraints: curve vertex " + std::to_string(v) + " names curve " +
                                        std::to_string(k) + ", not a polyline of >= 2 points (of " +
                                        std::to_string(curves.size()) + " curves)");
    }
}

}  // namespace dualhex::mesher

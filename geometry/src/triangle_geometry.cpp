#include "dualhex/geometry/triangle_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace dualhex::geometry {

using Eigen::Vector3d;

Vector3d closest_point_on_triangle(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c) {
    const Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
    const Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double denom = va + vb + vc;
    if (!(denom > 0)) {  // degenerate triangle: nearest of its three edges' endpoints
        const Vector3d* best = &a;
        for (const Vector3d* q : {&b, &c})
            if ((*q - p).squaredNorm() < (*best - p).squaredNorm()) best = q;
        return *best;
    }
    const double v = vb / denom, w = vc / denom;
    return a + v * ab + w * ac;
}

bool triangle_box_overlap(const Eigen::AlignedBox3d& box, const Vector3d& a, const Vector3d& b, const Vector3d& c) {
    const Vector3d center = box.center();
    const Vector3d h = 0.5 * (box.max() - box.min());
    const Vector3d v[3] = {a - center, b - center, c - center};
    auto separated = [&](const Vector3d& axis) {
        const double p0 = axis.dot(v[0]), p1 = axis.dot(v[1]), p2 = axis.dot(v[2]);
        const double r = h.x() * std::abs(axis.x()) + h.y() * std::abs(axis.y()) + h.z() * std::abs(axis.z());
        return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
    };
    for (int axis = 0; axis < 3; ++axis) {  // box face normals = bounding-box overlap
        const double lo = std::min({v[0][axis], v[1][axis], v[2][axis]});
        const double hi = std::max({v[0][axis], v[1][axis], v[2][axis]});
        if (lo > h[axis] || hi < -h[axis]) return false;
    }
    const Vector3d e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    if (separated(e[0].cross(e[1]))) return false;  // triangle plane
    for (const auto& edge : e)
        for (int axis = 0; axis < 3; ++axis)
            if (separated(Vector3d::Unit(axis).cross(edge))) return false;
    return true;
}

std::optional<RayTriangleHit> ray_triangle(const Vector3d& origin, const Vector3d& dir, const Vector3d& a,
                                           const Vector3d& b, const Vector3d& c, double t_min) {
    const Vector3d e1 = b - a, e2 = c - a;
    const Vector3d pv = dir.cross(e2);
    const double det = e1.dot(pv);
    const double scale = e1.norm() * e2.norm() * dir.norm();
    if (!(std::abs(det) > 1e-14 * scale)) return std::nullopt;  // parallel or degenerate
    const double inv = 1.0 / det;
    const Vector3d tv = origin - a;
    const double u = tv.dot(pv) * inv;
    if (u < 0 || u > 1) return std::nullopt;
    const Vector3d qv = tv.cross(e1);
    const double v = dir.dot(qv) * inv;
    if (v < 0 || u + v > 1) return std::nullopt;
    const double t = e2.dot(qv) * inv;
    if (!(t > t_min)) return std::nullopt;
    return RayTriangleHit{t, u, v};
}

double solid_angle(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c) {
    const Vector3d x = a - p, y = b - p, z = c - p;
    const double lx = x.norm(), ly = y.norm(), lz = z.norm();
    const double num = x.dot(y.cross(z));
    const double den = lx * ly * lz + x.dot(y) * lz + y.dot(z) * lx + z.dot(x) * ly;
    return 2.0 * std::atan2(num, den);
}

}  // namespace dualhex::geometry

// Two-sided hex-boundary / surface distance (surface_distance.hpp).
#include "dualhex/geometry/surface_distance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dualhex/geometry/hex_topology.hpp"

namespace dualhex::geometry {
namespace {

using Eigen::Vector3d;

// Samples every triangle of `from` on its barycentric grid; distances to `to`. A vertex
// is a sample of every triangle around it: its distance is computed once.
DirectedDistance directed_distance(const TriangleSurface& from, const AabbTree& to, double spacing,
                                   int max_subdivisions) {
    DirectedDistance d;
    std::vector<double> vertex_distance(from.vertices.size(), -1.0);
    const auto distance_at = [&](int v) {
        double& dv = vertex_distance[static_cast<std::size_t>(v)];
        if (dv < 0) dv = std::sqrt(to.squared_distance(from.vertices[static_cast<std::size_t>(v)]));
        return dv;
    };
    double weighted = 0, area_sum = 0;
    for (const auto& t : from.triangles) {
        const Vector3d& a = from.vertices[static_cast<std::size_t>(t[0])];
        const Vector3d& b = from.vertices[static_cast<std::size_t>(t[1])];
        const Vector3d& c = from.vertices[static_cast<std::size_t>(t[2])];
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        const int n = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 1, max_subdivisions);
        const double area = 0.5 * (b - a).cross(c - a).norm();
        const auto count = static_cast<double>((n + 1) * (n + 2) / 2);
        double sum = 0;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const Vector3d p = a + (b - a) * (static_cast<double>(i) / n) + (c - a) * (static_cast<double>(j) / n);
                const int corner = i == 0 && j == 0 ? t[0] : i == n ? t[1] : j == n ? t[2] : -1;
                const double dist = corner >= 0 ? distance_at(corner) : std::sqrt(to.squared_distance(p));
                sum += dist;
                ++d.samples;
                if (dist > d.max) {
                    d.max = dist;
                    d.farthest = corner >= 0 ? from.vertices[static_cast<std::size_t>(corner)] : p;
                }
            }
        weighted += area * sum / count;
        area_sum += area;
    }
    d.mean = area_sum > 0 ? weighted / area_sum : 0;
    return d;
}

}  // namespace

TriangleSurface boundary_triangles(const HexMesh& mesh) {
    TriangleSurface s;
    s.source = "<hex mesh boundary>";
    s.vertices = mesh.points;
    for (const auto& q : boundary_defects(mesh.hexes, mesh.points.size()).quads) {
        s.triangles.push_back({q[0], q[1], q[2]});
        s.triangles.push_back({q[0], q[2], q[3]});
    }
    return s;
}

SurfaceDistance surface_distance(const HexMesh& mesh, const AabbTree& surface, const SurfaceDistanceOptions& options) {
    if (!(options.sample_spacing > 0) || options.max_subdivisions < 1 || !(options.on_surface_tolerance >= 0))
        throw std::invalid_argument(
            "surface distance: sample spacing must be > 0, max subdivisions >= 1, tolerance >= 0");
    TriangleSurface boundary = boundary_triangles(mesh);
    if (boundary.triangles.empty()) throw std::invalid_argument("surface distance: the hex mesh has no boundary quads");
    SurfaceDistance r;
    r.diagonal = surface.bounds().diagonal().norm();
    const double spacing = options.sample_spacing * (r.diagonal > 0 ? r.diagonal : 1.0);
    std::vector<char> on_boundary(mesh.points.size(), 0);
    for (const auto& t : boundary.triangles)
        for (int v : t) on_boundary[static_cast<std::size_t>(v)] = 1;
    std::size_t close = 0;
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
        if (on_boundary[v]) {
            ++r.boundary_vertices;
            close += std::sqrt(surface.squared_distance(mesh.points[v])) <= options.on_surface_tolerance * r.diagonal;
        }
    r.share_vertices_on_surface = static_cast<double>(close) / static_cast<double>(r.boundary_vertices);
    r.mesh_to_surface = directed_distance(boundary, surface, spacing, options.max_subdivisions);
    const AabbTree boundary_tree(std::move(boundary));
    r.surface_to_mesh = directed_distance(surface.surface(), boundary_tree, spacing, options.max_subdivisions);
    return r;
}

}  // namespace dualhex::geometry

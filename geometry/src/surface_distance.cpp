// Two-sided hex-boundary / surface distance (surface_distance.hpp).
#include "dualhex/geometry/surface_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/geometry/parallel_each.hpp"

namespace dualhex::geometry {
namespace {

using Eigen::Vector3d;

// Per vertex of `from` used by a triangle: its distance to `to` (-1 if unused).
std::vector<double> vertex_distances(const TriangleSurface& from, const AabbTree& to) {
    std::vector<double> out(from.vertices.size(), -1.0);
    for (const auto& t : from.triangles)
        for (int v : t) out[static_cast<std::size_t>(v)] = 0;
    parallel_each(out.size(), 256, [&](std::size_t v) {
        if (out[v] == 0) out[v] = std::sqrt(to.squared_distance(from.vertices[v]));
    });
    return out;
}

// One triangle's samples: their sum and count, the first farthest one.
struct TriangleSamples {
    double sum = 0, area = 0, max = 0;
    std::size_t samples = 0;
    Vector3d farthest = Vector3d::Zero();
};

// Samples triangle t of `from` on its barycentric grid; its corners' distances are known.
TriangleSamples sample_triangle(const TriangleSurface& from, const std::array<int, 3>& t, const AabbTree& to,
                                const std::vector<double>& vertex_distance, double spacing, int max_subdivisions) {
    TriangleSamples s;
    const Vector3d& a = from.vertices[static_cast<std::size_t>(t[0])];
    const Vector3d& b = from.vertices[static_cast<std::size_t>(t[1])];
    const Vector3d& c = from.vertices[static_cast<std::size_t>(t[2])];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int n = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 1, max_subdivisions);
    s.area = 0.5 * (b - a).cross(c - a).norm();
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const Vector3d p = a + (b - a) * (static_cast<double>(i) / n) + (c - a) * (static_cast<double>(j) / n);
            const int corner = i == 0 && j == 0 ? t[0] : i == n ? t[1] : j == n ? t[2] : -1;
            const double dist =
                corner >= 0 ? vertex_distance[static_cast<std::size_t>(corner)] : std::sqrt(to.squared_distance(p));
            s.sum += dist;
            ++s.samples;
            if (dist > s.max) {
                s.max = dist;
                s.farthest = corner >= 0 ? from.vertices[static_cast<std::size_t>(corner)] : p;
            }
        }
    return s;
}

// Samples every triangle of `from` on its barycentric grid; distances to `to`. The
// triangles are sampled in parallel and combined in triangle order (the sums, and the
// first farthest sample on ties, as one serial pass would give them).
DirectedDistance directed_distance(const TriangleSurface& from, const AabbTree& to, double spacing,
                                   int max_subdivisions) {
    const std::vector<double> vertex_distance = vertex_distances(from, to);
    std::vector<TriangleSamples> per_triangle(from.triangles.size());
    parallel_each(per_triangle.size(), 64, [&](std::size_t i) {
        per_triangle[i] = sample_triangle(from, from.triangles[i], to, vertex_distance, spacing, max_subdivisions);
    });
    DirectedDistance d;
    double weighted = 0, area_sum = 0;
    for (const TriangleSamples& s : per_triangle) {
        d.samples += s.samples;
        if (s.max > d.max) {
            d.max = s.max;
            d.farthest = s.farthest;
        }
        weighted += s.area * s.sum / static_cast<double>(s.samples);
        area_sum += s.area;
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
    std::vector<char> close(mesh.points.size(), 0);
    parallel_each(close.size(), 256, [&](std::size_t v) {
        close[v] = on_boundary[v] && std::sqrt(surface.squared_distance(mesh.points[v])) <=
                                         options.on_surface_tolerance * r.diagonal;
    });
    for (std::size_t v = 0; v < mesh.points.size(); ++v) r.boundary_vertices += on_boundary[v] ? 1 : 0;
    const auto n_close = static_cast<std::size_t>(std::count(close.begin(), close.end(), 1));
    r.share_vertices_on_surface = static_cast<double>(n_close) / static_cast<double>(r.boundary_vertices);
    r.mesh_to_surface = directed_distance(boundary, surface, spacing, options.max_subdivisions);
    const AabbTree boundary_tree(std::move(boundary));
    r.surface_to_mesh = directed_distance(surface.surface(), boundary_tree, spacing, options.max_subdivisions);
    return r;
}

}  // namespace dualhex::geometry

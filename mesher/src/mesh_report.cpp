// The report stage's figures (mesh_report.hpp).
#include "dualhex/mesher/mesh_report.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/surface_distance.hpp"
#include "hex_edges.hpp"

namespace dualhex::mesher {

std::map<int, std::size_t> interior_singular_edge_valences(const geometry::HexMesh& mesh) {
    std::unordered_map<std::uint64_t, int> hexes_at;
    hexes_at.reserve(mesh.hexes.size() * 4);
    for (const auto& h : mesh.hexes)
        for (const auto& e : detail::kHexEdges) ++hexes_at[detail::edge_key(h[e[0]], h[e[1]])];
    std::unordered_map<std::uint64_t, char> boundary;
    for (const auto& q : geometry::boundary_quads(mesh))
        for (int i = 0; i < 4; ++i) boundary[detail::edge_key(q[i], q[(i + 1) % 4])] = 1;
    std::map<int, std::size_t> out;
    for (const auto& [key, n] : hexes_at)
        if (n != 4 && !boundary.contains(key)) ++out[n];
    return out;
}

namespace {

// What left the inside hexes near a far point out: the most frequent leaving-out decision.
CoreFate cause_of(const std::array<std::size_t, kCoreFates>& fates) {
    CoreFate best = CoreFate::Core;
    std::size_t most = 0;
    for (CoreFate f : {CoreFate::Cut, CoreFate::DroppedPart, CoreFate::RepairOut, CoreFate::Thin})
        if (fates[static_cast<std::size_t>(f)] > most) {
            most = fates[static_cast<std::size_t>(f)];
            best = f;
        }
    return best;
}

}  // namespace

std::vector<FarSurfacePoint> far_surface_points(const geometry::HexMesh& mesh, const geometry::AabbTree& surface,
                                                const CoreSelection& core, double far, std::size_t max_points) {
    const geometry::AabbTree boundary(geometry::boundary_triangles(mesh));
    const geometry::TriangleSurface& s = surface.surface();
    std::vector<std::pair<double, Eigen::Vector3d>> samples;
    const auto sample = [&](const Eigen::Vector3d& p) {
        const double d = std::sqrt(boundary.squared_distance(p));
        if (d > far) samples.emplace_back(d, p);
    };
    for (const auto& v : s.vertices) sample(v);
    for (const auto& t : s.triangles)
        sample((s.vertices[static_cast<std::size_t>(t[0])] + s.vertices[static_cast<std::size_t>(t[1])] +
                s.vertices[static_cast<std::size_t>(t[2])]) / 3.0);
    std::stable_sort(samples.begin(), samples.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<FarSurfacePoint> out;
    for (const auto& [d, p] : samples) {
        if (out.size() >= max_points) break;
        const bool known = std::any_of(out.begin(), out.end(), [&](const FarSurfacePoint& f) {
            return (f.point - p).norm() <= f.distance;
        });
        if (known) continue;
        FarSurfacePoint f;
        f.point = p;
        f.distance = d;
        for (std::size_t h = 0; h < core.fate.size() && h < core.dual_centroid.size(); ++h)
            if (core.fate[h] != CoreFate::Outside && (core.dual_centroid[h] - p).norm() <= d)
                ++f.fates[static_cast<std::size_t>(core.fate[h])];
        f.cause = cause_of(f.fates);
        out.push_back(f);
    }
    return out;
}

}  // namespace dualhex::mesher

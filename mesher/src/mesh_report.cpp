// The report stage's figures (mesh_report.hpp).
#include "dualhex/mesher/mesh_report.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/surface_distance.hpp"
#include "far_samples.hpp"
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
    for (CoreFate f : {CoreFate::Cut, CoreFate::DroppedPart, CoreFate::RepairOut, CoreFate::CleanedOut, CoreFate::Thin})
        if (fates[static_cast<std::size_t>(f)] > most) {
            most = fates[static_cast<std::size_t>(f)];
            best = f;
        }
    return best;
}

}  // namespace

namespace {

// The places of `samples` (farthest first, one per ball of its distance), with the fates of
// the dual hexes within the distance of the input's point (for a hex-boundary sample: its
// closest input point, where the core should have reached).
void add_places(const std::vector<detail::FarSample>& samples, bool on_hex_boundary,
                const CoreSelection& core, std::size_t max_points, std::vector<FarSurfacePoint>& out) {
    const std::size_t first = out.size();
    for (const detail::FarSample& sample : samples) {
        const double d = sample.distance;
        const Eigen::Vector3d& p = sample.point;
        const Eigen::Vector3d& centre = on_hex_boundary ? sample.closest : sample.point;
        if (out.size() - first >= max_points) break;
        const bool known = std::any_of(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
                                       [&](const FarSurfacePoint& f) { return (f.point - p).norm() <= f.distance; });
        if (known) continue;
        FarSurfacePoint f;
        f.point = p;
        f.on_hex_boundary = on_hex_boundary;
        f.distance = d;
        for (std::size_t h = 0; h < core.fate.size() && h < core.dual_centroid.size(); ++h)
            if (core.fate[h] != CoreFate::Outside && (core.dual_centroid[h] - centre).norm() <= d)
                ++f.fates[static_cast<std::size_t>(core.fate[h])];
        f.cause = cause_of(f.fates);
        out.push_back(f);
    }
}

}  // namespace

std::vector<FarSurfacePoint> far_surface_points(const geometry::HexMesh& mesh, const geometry::AabbTree& surface,
                                                const CoreSelection& core, double far, std::size_t max_points) {
    const geometry::AabbTree boundary(geometry::boundary_triangles(mesh));
    std::vector<FarSurfacePoint> out;
    add_places(detail::far_samples(surface.surface(), boundary, far), false, core, max_points, out);
    add_places(detail::far_samples(boundary.surface(), surface, far), true, core, max_points, out);
    return out;
}

}  // namespace dualhex::mesher

// The pad stage (pad.hpp).
#include "dualhex/mesher/pad.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/geometry/parallel_each.hpp"
#include "dualhex/geometry/quality.hpp"
#include "hex_energy.hpp"

namespace dualhex::mesher {
namespace {

using Quads = std::vector<std::array<int, 4>>;

// Per point: the smoothed outward normal of the boundary quads at it (zero elsewhere), and
// the mean length of its boundary edges.
struct BoundaryFrame {
    std::vector<Eigen::Vector3d> normal;
    std::vector<double> edge;
};

BoundaryFrame boundary_frame(const geometry::HexMesh& core, const Quads& quads, int smoothing) {
    const std::size_t n = core.points.size();
    BoundaryFrame f{std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero()), std::vector<double>(n, 0)};
    std::vector<int> edges_at(n, 0);
    for (const auto& q : quads) {
        const auto& p = core.points;
        const auto u = static_cast<std::size_t>(q[0]), v = static_cast<std::size_t>(q[1]),
                   w = static_cast<std::size_t>(q[2]), x = static_cast<std::size_t>(q[3]);
        const Eigen::Vector3d area = 0.5 * (p[w] - p[u]).cross(p[x] - p[v]);  // outward, |.| = area
        for (int c : q) f.normal[static_cast<std::size_t>(c)] += area;
        for (int i = 0; i < 4; ++i) {  // each boundary edge is seen from its two quads
            const auto a = static_cast<std::size_t>(q[i]), b = static_cast<std::size_t>(q[(i + 1) % 4]);
            const double len = (p[a] - p[b]).norm();
            f.edge[a] += len;
            f.edge[b] += len;
            edges_at[a] += 1;
            edges_at[b] += 1;
        }
    }
    for (std::size_t v = 0; v < n; ++v)
        if (edges_at[v] > 0) f.edge[v] /= edges_at[v];
    for (int round = 0; round < smoothing; ++round) {
        std::vector<Eigen::Vector3d> next(n, Eigen::Vector3d::Zero());
        for (const auto& q : quads)  // each corner gets the unit normals of the quad's corners
            for (int c : q)
                for (int d : q) next[static_cast<std::size_t>(c)] += f.normal[static_cast<std::size_t>(d)].normalized();
        f.normal = std::move(next);
    }
    for (auto& v : f.normal)
        if (v.squaredNorm() > 0) v.normalize();
    return f;
}

// Per boundary point (image[v] >= 0) its two surface candidates: the hit of the ray along
// the smoothed normal, taken if it is within ray_limit x (distance + edge), else the
// closest point. Each point's queries are independent: computed in parallel.
struct OuterCandidates {
    Eigen::Vector3d taken = Eigen::Vector3d::Zero(), other = Eigen::Vector3d::Zero();
    bool by_ray = false;
};

std::vector<OuterCandidates> outer_candidates(const geometry::HexMesh& core, const std::vector<int>& image,
                                              const BoundaryFrame& frame, const geometry::AabbTree& tree,
                                              double ray_limit) {
    std::vector<OuterCandidates> out(core.points.size());
    geometry::parallel_each(out.size(), 64, [&](std::size_t v) {
        if (image[v] < 0) return;
        const Eigen::Vector3d& p = core.points[v];
        const geometry::ClosestPoint closest = tree.closest_point(p);
        const double limit = ray_limit * (std::sqrt(closest.squared_distance) + frame.edge[v]);
        const auto hit = frame.normal[v].squaredNorm() > 0 ? tree.first_hit(p, frame.normal[v]) : std::nullopt;
        if (hit && hit->t <= limit)
            out[v] = {hit->point, closest.point, true};
        else
            out[v] = {closest.point, hit ? hit->point : closest.point, false};
    });
    return out;
}

std::size_t inverted_at(const geometry::HexMesh& mesh, const detail::VertexHexes& hexes, std::size_t v) {
    std::size_t n = 0;
    for (std::size_t i = hexes.start[v]; i < hexes.start[v + 1]; ++i)
        n += geometry::scaled_jacobian(mesh, static_cast<std::size_t>(hexes.hex[i])) > 0 ? 0 : 1;
    return n;
}

// Each outer point has two surface candidates (the ray's hit and the closest point); at
// the points of inverted hexes, take the other one where that inverts fewer hexes there.
// Returns the number of points switched.
std::size_t switch_candidates(geometry::HexMesh& mesh, std::size_t first_outer,
                              std::vector<Eigen::Vector3d>& other) {
    const detail::VertexHexes hexes(mesh);
    std::size_t switched = 0;
    for (int round = 0; round < 3; ++round) {
        std::size_t this_round = 0;
        for (std::size_t v = first_outer; v < mesh.points.size(); ++v) {
            const std::size_t before = inverted_at(mesh, hexes, v);
            if (before == 0 || other[v - first_outer] == mesh.points[v]) continue;
            std::swap(mesh.points[v], other[v - first_outer]);
            if (inverted_at(mesh, hexes, v) < before) {
                ++this_round;
            } else {
                std::swap(mesh.points[v], other[v - first_outer]);
            }
        }
        switched += this_round;
        if (this_round == 0) break;
    }
    return switched;
}

}  // namespace

PadResult pad_layer(const geometry::HexMesh& core, const geometry::AabbTree& tree, const PadOptions& options) {
    const geometry::BoundaryDefects boundary = geometry::boundary_defects(core.hexes, core.points.size());
    if (boundary.quads.empty()) throw std::invalid_argument("pad: the core has no boundary quad");
    const BoundaryFrame frame = boundary_frame(core, boundary.quads, options.normal_smoothing);

    PadResult out;
    out.mesh = core;
    out.core_points = core.points.size();
    out.core_hexes = core.hexes.size();
    std::vector<int> image(core.points.size(), -1);
    std::vector<Eigen::Vector3d> other;  // (outer points): the candidate not taken
    for (const auto& q : boundary.quads)
        for (int c : q) image[static_cast<std::size_t>(c)] = 0;
    const std::vector<OuterCandidates> candidates = outer_candidates(core, image, frame, tree, options.ray_limit);
    for (std::size_t v = 0; v < core.points.size(); ++v) {  // numbered in vertex order
        if (image[v] < 0) continue;
        image[v] = static_cast<int>(out.mesh.points.size());
        out.mesh.points.push_back(candidates[v].taken);
        other.push_back(candidates[v].other);
        ++(candidates[v].by_ray ? out.by_ray : out.by_closest_point);
    }
    for (const auto& q : boundary.quads) {
        std::array<int, 8> h{};
        for (int i = 0; i < 4; ++i) {
            h[static_cast<std::size_t>(i)] = q[static_cast<std::size_t>(i)];
            h[static_cast<std::size_t>(i + 4)] = image[static_cast<std::size_t>(q[static_cast<std::size_t>(i)])];
        }
        out.mesh.hexes.push_back(h);
    }
    out.pad_hexes = boundary.quads.size();
    out.switched = switch_candidates(out.mesh, out.core_points, other);
    out.surface_vertices = out.mesh.points.size() - out.core_points;
    out.constraints = VertexConstraints::interior(out.mesh.points.size());
    for (std::size_t v = out.core_points; v < out.mesh.points.size(); ++v) out.constraints.role[v] = VertexRole::Surface;
    return out;
}

}  // namespace dualhex::mesher

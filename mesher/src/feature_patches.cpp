// The features stage's last step (feature_patches.hpp): Surface vertices onto the patch of
// their boundary region.
#include "dualhex/mesher/feature_patches.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "dualhex/geometry/parallel_each.hpp"
#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/triangle_geometry.hpp"
#include "hex_edges.hpp"

namespace dualhex::mesher {
namespace {

using geometry::HexMesh;

int find(std::vector<int>& parent, int x) {
    while (parent[static_cast<std::size_t>(x)] != x)
        x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    return x;
}

constexpr int kNone = -1, kConflict = -2;

// Records that a slot wants `patch`: the first wish sticks, a different one is a conflict.
void wish(int& slot, int patch) {
    if (patch == kNone || slot == kConflict) return;
    slot = slot == kNone || slot == patch ? patch : kConflict;
}

std::uint64_t directed_key(int a, int b) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32 | static_cast<std::uint32_t>(b);
}

// The patch each boundary quad wants (kNone: no opinion, kConflict: two), by the sides of
// the path edges it walks, then spread over regions whose path-side quads agree.
std::vector<int> quad_wishes(const std::vector<std::array<int, 4>>& quads, const geometry::FeatureSet& features,
                             const std::vector<PathEdge>& path_edges) {
    std::unordered_map<std::uint64_t, int> curve_of;  // directed path edge -> curve
    std::unordered_set<std::uint64_t> cut;
    for (const PathEdge& e : path_edges) {
        curve_of[directed_key(e.from, e.to)] = e.curve;
        cut.insert(detail::edge_key(e.from, e.to));
    }
    std::vector<int> want(quads.size(), kNone), parent(quads.size());
    std::unordered_map<std::uint64_t, int> first_quad;  // undirected non-path edge -> a quad on it
    for (std::size_t q = 0; q < quads.size(); ++q) {
        parent[q] = static_cast<int>(q);
        for (std::size_t i = 0; i < 4; ++i) {
            const int a = quads[q][i], b = quads[q][(i + 1) % 4];
            for (int side = 0; side < 2; ++side) {  // walks the curve forward: left; backward: right
                const auto it = curve_of.find(side == 0 ? directed_key(a, b) : directed_key(b, a));
                if (it != curve_of.end())
                    wish(want[q], features.curves[static_cast<std::size_t>(it->second)].sides[static_cast<std::size_t>(side)]);
            }
            const std::uint64_t key = detail::edge_key(a, b);
            if (cut.contains(key)) continue;
            const auto [it, fresh] = first_quad.try_emplace(key, static_cast<int>(q));
            if (!fresh) {
                const int ra = find(parent, it->second), rb = find(parent, static_cast<int>(q));
                parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
            }
        }
    }
    std::unordered_map<int, int> region_want;
    for (std::size_t q = 0; q < quads.size(); ++q)
        if (want[q] != kNone) {
            int& slot = region_want.try_emplace(find(parent, static_cast<int>(q)), kNone).first->second;
            if (want[q] == kConflict) slot = kConflict;
            wish(slot, want[q]);
        }
    for (std::size_t q = 0; q < quads.size(); ++q)
        if (want[q] == kNone) {
            const auto it = region_want.find(find(parent, static_cast<int>(q)));
            if (it != region_want.end() && it->second >= 0) want[q] = it->second;
        }
    return want;
}

// The point of patch `triangles` nearest to p (brute force: few vertices move).
Eigen::Vector3d closest_on_patch(const geometry::TriangleSurface& s, const std::vector<int>& triangles,
                                 const Eigen::Vector3d& p) {
    Eigen::Vector3d best = p;
    double best_d = std::numeric_limits<double>::infinity();
    for (int t : triangles) {
        const auto& tri = s.triangles[static_cast<std::size_t>(t)];
        const Eigen::Vector3d q = geometry::closest_point_on_triangle(p, s.vertices[static_cast<std::size_t>(tri[0])],
                                                                      s.vertices[static_cast<std::size_t>(tri[1])],
                                                                      s.vertices[static_cast<std::size_t>(tri[2])]);
        if ((q - p).squaredNorm() < best_d) {
            best_d = (q - p).squaredNorm();
            best = q;
        }
    }
    return best;
}

}  // namespace

std::size_t project_to_patches(HexMesh& mesh, const geometry::AabbTree& tree, const geometry::FeatureSet& features,
                               const VertexConstraints& constraints,
                               const std::vector<PathEdge>& path_edges) {
    const geometry::TriangleSurface& s = tree.surface();
    if (features.patch.size() != s.triangles.size())
        throw std::invalid_argument("feature patches: " + std::to_string(features.patch.size()) +
                                    " patch ids for " + std::to_string(s.triangles.size()) + " triangles");
    if (constraints.role.size() != mesh.points.size())
        throw std::invalid_argument("feature patches: constraints do not match the mesh");
    for (const PathEdge& e : path_edges)
        if (e.curve < 0 || static_cast<std::size_t>(e.curve) >= features.curves.size() || e.from < 0 || e.to < 0 ||
            static_cast<std::size_t>(std::max(e.from, e.to)) >= mesh.points.size())
            throw std::invalid_argument("feature patches: path edge " + std::to_string(e.from) + "-" +
                                        std::to_string(e.to) + " of curve " + std::to_string(e.curve) + " out of range");
    if (path_edges.empty()) return 0;
    const auto quads = geometry::boundary_quads(mesh);
    const std::vector<int> quad_want = quad_wishes(quads, features, path_edges);
    std::vector<int> vertex_want(mesh.points.size(), kNone);
    std::vector<Eigen::Vector3d> neighbour_sum(mesh.points.size(), Eigen::Vector3d::Zero());
    std::vector<double> neighbour_count(mesh.points.size(), 0.0);  // each boundary edge seen from both quads
    for (std::size_t q = 0; q < quads.size(); ++q)
        for (std::size_t i = 0; i < 4; ++i) {
            const auto v = static_cast<std::size_t>(quads[q][i]);
            for (const std::size_t j : {(i + 1) % 4, (i + 3) % 4}) {
                neighbour_sum[v] += mesh.points[static_cast<std::size_t>(quads[q][j])];
                neighbour_count[v] += 1;
            }
        }
    for (std::size_t q = 0; q < quads.size(); ++q)
        for (int v : quads[q]) {
            int& slot = vertex_want[static_cast<std::size_t>(v)];
            if (quad_want[q] == kConflict) slot = kConflict;
            wish(slot, quad_want[q]);
        }
    std::vector<std::vector<int>> triangles_of(static_cast<std::size_t>(features.patches));
    for (std::size_t t = 0; t < features.patch.size(); ++t)
        triangles_of[static_cast<std::size_t>(features.patch[t])].push_back(static_cast<int>(t));
    // Each vertex's move reads only its own position and the sums above: computed in
    // parallel, one slot per vertex, then applied.
    std::vector<char> moves(mesh.points.size(), 0);
    std::vector<Eigen::Vector3d> target(mesh.points.size());
    geometry::parallel_each(mesh.points.size(), 256, [&](std::size_t v) {
        const int want = vertex_want[v];
        if (constraints.role[v] != VertexRole::Surface || want < 0 || want >= features.patches) return;
        const int now = features.patch[static_cast<std::size_t>(tree.closest_point(mesh.points[v]).triangle)];
        if (now == want) return;
        // the closest point of the wanted patch to the vertex itself would lie on the crease
        // (a flat quad): take it for the mean of its boundary neighbours, on its own side
        const Eigen::Vector3d mean = neighbour_sum[v] / neighbour_count[v];
        target[v] = closest_on_patch(s, triangles_of[static_cast<std::size_t>(want)], mean);
        moves[v] = 1;
    });
    std::size_t moved = 0;
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
        if (moves[v]) {
            mesh.points[v] = target[v];
            ++moved;
        }
    return moved;
}

}  // namespace dualhex::mesher

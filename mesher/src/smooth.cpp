// The smooth stage (smooth.hpp) and the quality state it keeps (quality_state.hpp).
#include "dualhex/mesher/smooth.hpp"

#include <algorithm>
#include <cstdint>

#include "dualhex/geometry/parallel_each.hpp"
#include "dualhex/geometry/quality.hpp"
#include "hex_edges.hpp"

namespace dualhex::mesher {
namespace {

// Vertex adjacency by hex edges as CSR: neighbours of v are adj[start[v] .. start[v+1]).
struct VertexAdjacency {
    std::vector<std::size_t> start;
    std::vector<int> adj;
};

VertexAdjacency hex_edge_adjacency(const geometry::HexMesh& mesh) {
    std::vector<std::uint64_t> edges;
    edges.reserve(mesh.hexes.size() * 12);
    for (const auto& h : mesh.hexes)
        for (const auto& e : detail::kHexEdges) edges.push_back(detail::edge_key(h[e[0]], h[e[1]]));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    VertexAdjacency out;
    out.start.assign(mesh.points.size() + 1, 0);
    for (auto k : edges) {
        ++out.start[(k >> 32) + 1];
        ++out.start[(k & 0xffffffffu) + 1];
    }
    for (std::size_t i = 1; i < out.start.size(); ++i) out.start[i] += out.start[i - 1];
    out.adj.resize(out.start.back());
    std::vector<std::size_t> fill(out.start.begin(), out.start.end() - 1);
    for (auto k : edges) {
        const auto a = static_cast<std::size_t>(k >> 32), b = static_cast<std::size_t>(k & 0xffffffffu);
        out.adj[fill[a]++] = static_cast<int>(b);
        out.adj[fill[b]++] = static_cast<int>(a);
    }
    return out;
}

}  // namespace

std::size_t count_inverted(const std::vector<double>& sj) {
    return static_cast<std::size_t>(std::count_if(sj.begin(), sj.end(), [](double s) { return !(s > 0); }));
}

std::size_t count_inverted(const geometry::HexMesh& mesh) { return count_inverted(geometry::scaled_jacobians(mesh)); }

QualityState quality_state(const geometry::HexMesh& mesh) {
    QualityState s{geometry::scaled_jacobians(mesh), 0};
    s.inverted = count_inverted(s.scaled_jacobian);
    return s;
}

int smooth_interior(geometry::HexMesh& mesh, const std::vector<char>& on_boundary, int iterations, QualityState& state) {
    if (iterations <= 0) return 0;
    const VertexAdjacency g = hex_edge_adjacency(mesh);
    int done = 0;
    std::vector<Eigen::Vector3d> next;
    for (int it = 0; it < iterations; ++it) {
        next = mesh.points;
        // A Jacobi step (each vertex from the old positions, into its own slot): parallel.
        geometry::parallel_each(mesh.points.size(), 1024, [&](std::size_t v) {
            if (on_boundary[v] || g.start[v] == g.start[v + 1]) return;
            Eigen::Vector3d m = Eigen::Vector3d::Zero();
            for (std::size_t i = g.start[v]; i < g.start[v + 1]; ++i) m += mesh.points[static_cast<std::size_t>(g.adj[i])];
            next[v] = m / static_cast<double>(g.start[v + 1] - g.start[v]);
        });
        std::swap(next, mesh.points);
        std::vector<double> sj_next = geometry::scaled_jacobians(mesh);
        const std::size_t inverted_next = count_inverted(sj_next);
        if (inverted_next > state.inverted) {  // rejected: restore and stop
            std::swap(next, mesh.points);
            break;
        }
        state.scaled_jacobian = std::move(sj_next);
        state.inverted = inverted_next;
        ++done;
    }
    return done;
}

}  // namespace dualhex::mesher

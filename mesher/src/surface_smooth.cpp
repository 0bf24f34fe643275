// The surface part of the smooth stage (surface_smooth.hpp).
#include "dualhex/mesher/surface_smooth.hpp"

#include <vector>

#include "dualhex/geometry/quality.hpp"
#include "hex_energy.hpp"

namespace dualhex::mesher {
namespace {

std::size_t inverted_at(const geometry::HexMesh& mesh, const detail::VertexHexes& hexes, std::size_t v) {
    std::size_t n = 0;
    for (std::size_t i = hexes.start[v]; i < hexes.start[v + 1]; ++i)
        n += geometry::scaled_jacobian(mesh, static_cast<std::size_t>(hexes.hex[i])) > 0 ? 0 : 1;
    return n;
}

}  // namespace

int smooth_surface(geometry::HexMesh& mesh, const VertexDomain& domain, int iterations, QualityState& state) {
    const std::vector<std::array<int, 4>> quads = geometry::boundary_quads(mesh);
    const std::size_t n = mesh.points.size();
    const detail::VertexHexes hexes(mesh);
    int done = 0;
    for (int it = 0; it < iterations; ++it) {
        std::vector<Eigen::Vector3d> sum(n, Eigen::Vector3d::Zero());
        std::vector<int> count(n, 0);
        for (const auto& q : quads)  // each edge seen from both quads: the weights stay equal
            for (int i = 0; i < 4; ++i) {
                const auto a = static_cast<std::size_t>(q[static_cast<std::size_t>(i)]);
                const auto b = static_cast<std::size_t>(q[static_cast<std::size_t>((i + 1) % 4)]);
                sum[a] += mesh.points[b];
                sum[b] += mesh.points[a];
                count[a] += 1;
                count[b] += 1;
            }
        std::size_t moved = 0;
        for (std::size_t v = 0; v < n; ++v) {
            if (domain.role(v) != VertexRole::Surface || count[v] == 0) continue;
            const Eigen::Vector3d x = mesh.points[v];
            const Eigen::Vector3d move = domain.restrict(v, x, 0.5 * (sum[v] / count[v] - x));
            const Eigen::Vector3d y = domain.project(v, x + move, x);
            const std::size_t before = inverted_at(mesh, hexes, v);
            mesh.points[v] = y;
            if (inverted_at(mesh, hexes, v) > before) {
                mesh.points[v] = x;  // refused: more inverted hexes at v
                continue;
            }
            ++moved;
        }
        if (moved == 0) break;
        ++done;
    }
    state = quality_state(mesh);
    return done;
}

}  // namespace dualhex::mesher

// The surface part of the smooth stage (surface_smooth.hpp).
#include "dualhex/mesher/surface_smooth.hpp"

#include <vector>

#include "dualhex/geometry/quality.hpp"

namespace dualhex::mesher {

int smooth_surface(geometry::HexMesh& mesh, const VertexDomain& domain, int iterations, QualityState& state) {
    const std::vector<std::array<int, 4>> quads = geometry::boundary_quads(mesh);
    const std::size_t n = mesh.points.size();
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
        std::vector<Eigen::Vector3d> next = mesh.points;
        for (std::size_t v = 0; v < n; ++v) {
            if (domain.role(v) != VertexRole::Surface || count[v] == 0) continue;
            const Eigen::Vector3d& x = mesh.points[v];
            const Eigen::Vector3d move = domain.restrict(v, x, 0.5 * (sum[v] / count[v] - x));
            next[v] = domain.project(v, x + move, x);
        }
        std::swap(next, mesh.points);
        std::vector<double> sj = geometry::scaled_jacobians(mesh);
        const std::size_t inverted = count_inverted(sj);
        if (inverted > state.inverted) {
            std::swap(next, mesh.points);
            break;
        }
        state.scaled_jacobian = std::move(sj);
        state.inverted = inverted;
        ++done;
    }
    return done;
}

}  // namespace dualhex::mesher

// The core boundary smoothed before the pad (core_boundary_smooth.hpp).
#include "dualhex/mesher/core_boundary_smooth.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/geometry/quality.hpp"
#include "hex_energy.hpp"

namespace dualhex::mesher {
namespace {

// Boundary-edge neighbours of each vertex (sorted, unique; empty off the boundary).
std::vector<std::vector<int>> boundary_neighbours(const geometry::HexMesh& core) {
    std::vector<std::vector<int>> nb(core.points.size());
    for (const auto& q : geometry::boundary_defects(core.hexes, core.points.size()).quads)
        for (std::size_t i = 0; i < 4; ++i) {
            nb[static_cast<std::size_t>(q[i])].push_back(q[(i + 1) % 4]);
            nb[static_cast<std::size_t>(q[(i + 1) % 4])].push_back(q[i]);
        }
    for (auto& n : nb) {
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
    }
    return nb;
}

// True if every hex at v has scaled Jacobian >= min(floor, before[h]).
bool keeps_floor(const geometry::HexMesh& core, const detail::VertexHexes& at, std::size_t v,
                 const std::vector<double>& before, double floor) {
    for (std::size_t i = at.start[v]; i < at.start[v + 1]; ++i) {
        const auto h = static_cast<std::size_t>(at.hex[i]);
        if (!(geometry::scaled_jacobian(core, h) >= std::min(floor, before[h]))) return false;
    }
    return true;
}

}  // namespace

std::size_t smooth_core_boundary(geometry::HexMesh& core, int iterations, double floor) {
    const std::vector<std::vector<int>> nb = boundary_neighbours(core);
    const detail::VertexHexes at(core);
    std::vector<double> sj = geometry::scaled_jacobians(core);
    std::size_t moves = 0;
    for (int it = 0; it < iterations; ++it) {
        std::size_t moved = 0;
        for (std::size_t v = 0; v < core.points.size(); ++v) {
            if (nb[v].empty()) continue;
            Eigen::Vector3d mean = Eigen::Vector3d::Zero();
            for (int u : nb[v]) mean += core.points[static_cast<std::size_t>(u)];
            mean /= static_cast<double>(nb[v].size());
            const Eigen::Vector3d x = core.points[v];
            for (double f : {0.5, 0.25}) {
                core.points[v] = x + f * (mean - x);
                if (keeps_floor(core, at, v, sj, floor)) break;
                core.points[v] = x;
            }
            if (core.points[v] == x) continue;
            ++moved;
            for (std::size_t i = at.start[v]; i < at.start[v + 1]; ++i)
                sj[static_cast<std::size_t>(at.hex[i])] = geometry::scaled_jacobian(core, static_cast<std::size_t>(at.hex[i]));
        }
        moves += moved;
        if (moved == 0) break;
    }
    return moves;
}

}  // namespace dualhex::mesher

// The restore stage (feature_restore.hpp).
#include "dualhex/mesher/feature_restore.hpp"

#include <algorithm>
#include <stdexcept>

#include "dualhex/geometry/quality.hpp"

namespace dualhex::mesher {
namespace {

// Moves v to p iff no hex around it becomes inverted or newly drops below `below`;
// updates the hexes' values when it does.
bool try_move(geometry::HexMesh& mesh, std::size_t v, const Eigen::Vector3d& p, const std::vector<int>& hexes,
              double below, std::vector<double>& sj) {
    const Eigen::Vector3d old = mesh.points[v];
    mesh.points[v] = p;
    std::vector<double> next;
    for (int h : hexes) {
        const double before = sj[static_cast<std::size_t>(h)];
        const double after = geometry::scaled_jacobian(mesh, static_cast<std::size_t>(h));
        if (!(after > 0) || (after < below && !(after >= before))) {
            mesh.points[v] = old;
            return false;
        }
        next.push_back(after);
    }
    for (std::size_t i = 0; i < hexes.size(); ++i) sj[static_cast<std::size_t>(hexes[i])] = next[i];
    return true;
}

}  // namespace

std::size_t restore_features(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& targets,
                             const VertexConstraints& constraints, double below, int rounds, QualityState& state) {
    const std::size_t n = mesh.points.size();
    if (targets.size() != n || constraints.role.size() != n)
        throw std::invalid_argument("restore: targets and constraints must have one entry per mesh point");
    std::vector<std::vector<int>> hexes_at(n);
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
        for (int v : mesh.hexes[h]) hexes_at[static_cast<std::size_t>(v)].push_back(static_cast<int>(h));
    std::size_t moves = 0;
    for (int round = 0; round < rounds; ++round) {
        std::size_t kept = 0;
        for (std::size_t v = 0; v < n; ++v) {
            const VertexRole r = constraints.role[v];
            if ((r != VertexRole::Curve && r != VertexRole::Corner) || mesh.points[v] == targets[v]) continue;
            for (const double t : {1.0, 0.5}) {
                const Eigen::Vector3d p = t == 1.0 ? targets[v] : Eigen::Vector3d(mesh.points[v] + t * (targets[v] - mesh.points[v]));
                if (try_move(mesh, v, p, hexes_at[v], below, state.scaled_jacobian)) {
                    ++kept;
                    break;
                }
            }
        }
        moves += kept;
        if (kept == 0) break;
    }
    state.inverted = count_inverted(state.scaled_jacobian);
    return moves;
}

}  // namespace dualhex::mesher

// The untangle stage (untangle.hpp).
#include "dualhex/mesher/untangle.hpp"

#include <algorithm>

#include "dualhex/geometry/quality.hpp"

namespace dualhex::mesher {

std::size_t untangle_towards(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& unprojected, int rounds,
                             double below, QualityState& state) {
    auto is_bad = [&](double q) { return !(q > 0) || q < below; };
    auto count_bad = [&](const std::vector<double>& values) {
        return static_cast<std::size_t>(std::count_if(values.begin(), values.end(), is_bad));
    };
    std::size_t bad = count_bad(state.scaled_jacobian), moves = 0;
    for (int round = 0; round < rounds && bad > 0; ++round) {
        std::vector<char> move(mesh.points.size(), 0);
        for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
            if (is_bad(state.scaled_jacobian[h]))
                for (int v : mesh.hexes[h]) move[static_cast<std::size_t>(v)] = 1;
        const std::vector<Eigen::Vector3d> before = mesh.points;
        std::size_t moved = 0;
        for (std::size_t v = 0; v < mesh.points.size(); ++v)
            if (move[v]) {
                mesh.points[v] = unprojected[v] + 0.5 * (mesh.points[v] - unprojected[v]);
                ++moved;
            }
        std::vector<double> sj_next = geometry::scaled_jacobians(mesh);
        const std::size_t inverted_next = count_inverted(sj_next), bad_next = count_bad(sj_next);
        if (inverted_next > state.inverted || (inverted_next == state.inverted && bad_next > bad)) {
            mesh.points = before;
            break;
        }
        moves += moved;
        state.scaled_jacobian = std::move(sj_next);
        state.inverted = inverted_next;
        bad = bad_next;
    }
    return moves;
}

}  // namespace dualhex::mesher

// Freeing the hexes the optimiser left flat or inverted (optimise_release.hpp).
#include "dualhex/mesher/optimise_release.hpp"

#include <algorithm>
#include <array>

#include "dualhex/geometry/quality.hpp"
#include "place_guard.hpp"

namespace dualhex::mesher {
namespace {

std::vector<std::size_t> hexes_at_most(const std::vector<double>& sj, double flat) {
    std::vector<std::size_t> out;
    for (std::size_t h = 0; h < sj.size(); ++h)
        if (!(sj[h] > flat)) out.push_back(h);
    return out;
}

// The scaled corner determinant of hex h at its corner k (the corner's three unit edges,
// right-handed in VTK order), as geometry::scaled_jacobian takes the minimum of.
double corner_scaled_det(const geometry::HexMesh& mesh, std::size_t h, std::size_t k) {
    static constexpr std::array<std::array<int, 3>, 8> kNeighbours{
        {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}}};
    const auto& hex = mesh.hexes[h];
    const Eigen::Vector3d& p = mesh.points[static_cast<std::size_t>(hex[k])];
    std::array<Eigen::Vector3d, 3> e;
    for (std::size_t i = 0; i < 3; ++i) {
        e[i] = mesh.points[static_cast<std::size_t>(hex[static_cast<std::size_t>(kNeighbours[k][i])])] - p;
        if (!(e[i].norm() > 0)) return 0;
        e[i].normalize();
    }
    return e[0].dot(e[1].cross(e[2]));
}

// Releases the roles in `which` of the vertices of `hexes` to Surface (with `at_bad_corners`
// only where the hex's corner is <= flat: the middle of three collinear quad corners);
// counts into `result`.
void release(const geometry::HexMesh& mesh, const std::vector<std::size_t>& hexes, VertexRole which,
             bool at_bad_corners, double flat, VertexConstraints& c, ReleaseResult& result) {
    for (std::size_t h : hexes)
        for (std::size_t k = 0; k < 8; ++k) {
            const auto u = static_cast<std::size_t>(mesh.hexes[h][k]);
            if (c.role[u] != which) continue;
            if (at_bad_corners && corner_scaled_det(mesh, h, k) > flat) continue;
            c.role[u] = VertexRole::Surface;
            c.curve[u] = -1;
            ++(which == VertexRole::Curve ? result.curves_released : result.corners_released);
        }
}

// The roles released in this step (differing from `roles`) of the vertices that did not
// move or were put back: their release changed nothing, so they keep their role (no
// crease where nothing moved) and are not counted.
void keep_unmoved_roles(const geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& before,
                        const VertexConstraints& roles, VertexConstraints& c, ReleaseResult& result) {
    for (std::size_t u = 0; u < mesh.points.size(); ++u) {
        if (c.role[u] == roles.role[u] || mesh.points[u] != before[u]) continue;
        --(roles.role[u] == VertexRole::Curve ? result.curves_released : result.corners_released);
        c.role[u] = roles.role[u];
        c.curve[u] = roles.curve[u];
    }
}

}  // namespace

ReleaseResult release_stuck_hexes(geometry::HexMesh& mesh, VertexConstraints& constraints,
                                  const geometry::AabbTree& tree, const FeatureCurves& curves,
                                  const OptimiseOptions& options, QualityState& state, double flat) {
    ReleaseResult result;
    std::vector<std::size_t> bad = hexes_at_most(state.scaled_jacobian, flat);
    result.bad_before = bad.size();
    OptimiseOptions local = options;
    local.bad_below = flat;
    local.rescue_rounds = 1;
    // 0: as they are; 1: the Curve vertices at their flat or inverted corners released;
    // 2: all their Curve vertices; 3: their Corner vertices too. Fewest released first: each
    // released vertex may leave a crease.
    for (int step = 0; step < 4 && !bad.empty(); ++step) {
        const std::vector<Eigen::Vector3d> points = mesh.points;
        const VertexConstraints roles = constraints;
        const ReleaseResult counts = result;
        if (step >= 1) release(mesh, bad, VertexRole::Curve, step == 1, flat, constraints, result);
        if (step >= 3) release(mesh, bad, VertexRole::Corner, false, flat, constraints, result);
        if (step >= 1 && result.curves_released == counts.curves_released &&
            result.corners_released == counts.corners_released)
            continue;  // nothing held them: the same run again would change nothing
        result.work += optimise_region(mesh, bad, 2, constraints, tree, curves, local).work;
        // The run's own contract is on all its hexes at once (and leaves out the hexes
        // <= flat): one place's loss hides behind another's gain. Each place judged alone.
        result.places_restored += detail::restore_worse_places(mesh, points, state.scaled_jacobian, flat).restored;
        keep_unmoved_roles(mesh, points, roles, constraints, result);
        const QualityState after = quality_state(mesh);
        const std::vector<std::size_t> left = hexes_at_most(after.scaled_jacobian, flat);
        if (left.size() < bad.size() && after.inverted <= state.inverted) {
            state = after;
            bad = left;
        } else {
            mesh.points = points;
            constraints = roles;
            const std::size_t work = result.work, restored = result.places_restored;
            result = counts;
            result.work = work;
            result.places_restored = restored;
        }
    }
    result.bad_after = bad.size();
    return result;
}

}  // namespace dualhex::mesher

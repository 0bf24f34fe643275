#pragma once
// Mesh quality.
//
// Scaled Jacobian of a hex (VTK_HEXAHEDRON order), the standard (Verdict) definition:
// at each of the 8 corners, the determinant of the three unit edge vectors to its
// neighbours, taken in the right-handed order of the reference cube; the hex's value is
// the minimum over the corners. 1 for a cube (any size/position), < 0 for an inverted or
// tangled hex, 0 if a corner has a zero-length edge.
//
// Hausdorff distance (one-sided, sampled): from the boundary of a hex mesh to a surface.
// Samples: the vertices and the centres of the boundary quads (faces of exactly one hex).
// Distances are divided by the surface's bounding-box diagonal.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::geometry {

/// For corner c of a hex: its neighbours (a, b, d) such that (x[a]-x[c], x[b]-x[c], x[d]-x[c])
/// is right-handed on the reference cube (VTK order, as Verdict).
inline constexpr int kScaledJacobianCorners[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                                      {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};

/// One corner's term: det of the unit edge vectors from `corner` to a, b, d; nullopt if an
/// edge has length 0 (or NaN), which makes the whole hex's value 0. scaled_jacobian is the
/// minimum of the 8 terms in corner order (NaN terms do not lower it); code that re-evaluates
/// only some corners and folds the same way gets the same bits.
[[nodiscard]] inline std::optional<double> corner_scaled_jacobian(const Eigen::Vector3d& corner, const Eigen::Vector3d& a,
                                                                  const Eigen::Vector3d& b, const Eigen::Vector3d& d) {
    Eigen::Vector3d e[3] = {a - corner, b - corner, d - corner};
    for (Eigen::Vector3d& v : e) {
        const double len = v.norm();
        if (!(len > 0)) return std::nullopt;
        v /= len;
    }
    return e[0].dot(e[1].cross(e[2]));
}

[[nodiscard]] double scaled_jacobian(const std::array<Eigen::Vector3d, 8>& corners);
[[nodiscard]] double scaled_jacobian(const HexMesh& mesh, std::size_t hex);
/// One value per hex.
[[nodiscard]] std::vector<double> scaled_jacobians(const HexMesh& mesh);

struct QualitySummary {
    std::size_t hexes = 0;
    double min = 0, mean = 0;
    double share_negative = 0;  ///< fraction of hexes with SJ < 0
    double share_below_02 = 0;  ///< fraction of hexes with SJ < 0.2
};
[[nodiscard]] QualitySummary summarize(const std::vector<double>& scaled_jacobians);

/// The boundary quads of a hex mesh (faces used by exactly one hex), corner order as in
/// the hex, outward.
[[nodiscard]] std::vector<std::array<int, 4>> boundary_quads(const HexMesh& mesh);

struct HausdorffResult {
    std::size_t samples = 0;
    double max = 0;   ///< max sample distance / bbox diagonal
    double mean = 0;  ///< mean sample distance / bbox diagonal
};
/// One-sided: boundary of `mesh` -> surface of `tree`.
[[nodiscard]] HausdorffResult boundary_to_surface_distance(const HexMesh& mesh, const AabbTree& tree);

}  // namespace dualhex::geometry

#pragma once
// Internal to the optimise stage: the per-hex corner tetrahedra, the regularised barrier
// energy of Garanzha, Kaporin, Kudryavtseva, Protais, Ray, Sokolov, "Foldover-free maps in
// 50 lines of code" (ACM TOG 40(4), 2021), in 3D, and the vertex -> hexes incidence.
//
// Corner tet k of a hex: J = [p_a - p_k, p_b - p_k, p_c - p_k] * s, (a, b, c) = the three
// neighbours of k in the reference cube's right-handed order (the scaled Jacobian's
// corners), s = 1 / (the hex's mean edge length in the input), so J = I on a cube of
// the input's size. With D = det J and chi(D, eps) = (D + sqrt(eps^2 + D^2)) / 2:
//   f_eps(J) = tr(J^T J) / chi(D, eps)^(2/3)  +  lambda * (D^2 + 1) / chi(D, eps)
// (shape: 3 at a conformal J, for any size; volume: 2 at D = 1). chi > 0 for every D, so
// f_eps is finite on tangled meshes; as eps -> 0 it becomes a barrier at D = 0.
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::mesher::detail {

/// Neighbours of each VTK hex corner, right-handed (Verdict's corner order).
inline constexpr std::array<std::array<int, 3>, 8> kCornerNeighbours{
    {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}}};

/// Hexes at each vertex, CSR: hexes of v are hex[start[v] .. start[v+1]).
struct VertexHexes {
    std::vector<std::size_t> start;
    std::vector<int> hex;
    explicit VertexHexes(const geometry::HexMesh& mesh);
    [[nodiscard]] std::size_t count(std::size_t v) const { return start[v + 1] - start[v]; }
};

struct BarrierEnergy {
    double eps = 1.0;
    double lambda = 1.0;
    std::vector<double> scale;  ///< (hexes): 1 / input mean edge length

    explicit BarrierEnergy(const geometry::HexMesh& mesh);

    /// f_eps of one Jacobian; `gradient` (optional) receives df/dJ.
    [[nodiscard]] double corner(const Eigen::Matrix3d& J, Eigen::Matrix3d* gradient) const;
    /// Sum of f_eps over the corners of hex h whose tet contains point `moved` (all 8 if
    /// moved < 0), with `moved` at `at`; `gradient` (optional) += d/d(at) of it.
    [[nodiscard]] double hex(const geometry::HexMesh& mesh, std::size_t h, int moved, const Eigen::Vector3d& at,
                             Eigen::Vector3d* gradient) const;
    /// The same local sum as hex(h, moved, at), with its exact gradient and Hessian in `at`
    /// (both added to). Along one vertex's position det J is affine (J changes by a rank-one
    /// term) and tr(J^T J) quadratic, so per corner the Hessian is closed form (no finite
    /// differences; hex_energy.cpp).
    double hex_newton(const geometry::HexMesh& mesh, std::size_t h, int moved, const Eigen::Vector3d& at,
                      Eigen::Vector3d& gradient, Eigen::Matrix3d& hessian) const;
    /// Minimum det J over the 8 corners of hex h (scaled as above).
    [[nodiscard]] double min_det(const geometry::HexMesh& mesh, std::size_t h) const;
};

/// The corner Jacobian (unscaled) of corner k of hex h, point `moved` at `at`.
[[nodiscard]] Eigen::Matrix3d corner_jacobian(const geometry::HexMesh& mesh, std::size_t h, int k, int moved,
                                              const Eigen::Vector3d& at);

}  // namespace dualhex::mesher::detail

#pragma once
// Why hexes are bad: a diagnostic of the padded mesh (core hexes first, then one pad hex
// per core boundary quad, pad.hpp), for the benchmark and the tests, not a pipeline stage.
//
// Input : the mesh (pad hexes after the first core_hexes; pad hex = base quad 0..3 on the
//         core, top quad 4..7 on the surface), its roles, per-hex scaled Jacobian, a
//         threshold.
// Output: PadDiagnosis — of the hexes with scaled Jacobian below the threshold (NaN
//         counts as below): how many are core / pad hexes, inverted or flat (<= 1e-6), and
//         per pad hex the causes it shows (not exclusive): a base edge on a convex or a
//         concave fold of the core boundary (neighbour base quad turned by more than 45
//         degrees), a base vertex with != 4 core boundary quads (a core corner), a top
//         quad collapsed (a top edge < 0.25 x the mean base edge: outer points bunched on
//         the surface), a thin pad (mean base-to-top distance < 0.25 x the mean base edge),
//         a vertex on a feature (Curve/Corner role), a base on an exposed core hex (one
//         with >= 3 boundary faces: a core corner, ridge or spike, core_cleanup.hpp).
#include <cstddef>
#include <string>
#include <vector>

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/vertex_constraints.hpp"

namespace dualhex::mesher {

struct PadDiagnosis {
    double threshold = 0.3;
    std::size_t core_below = 0, pad_below = 0;        ///< hexes below the threshold
    std::size_t core_inverted = 0, pad_inverted = 0;  ///< of them, inverted or flat
    // Pad hexes below the threshold showing each cause (a hex may show several).
    std::size_t convex_edge = 0, concave_edge = 0, irregular_vertex = 0, collapsed_top = 0, thin = 0,
                feature = 0, exposed_base = 0, none = 0;
    [[nodiscard]] std::string summary() const;
};

[[nodiscard]] PadDiagnosis diagnose_pad(const geometry::HexMesh& mesh, std::size_t core_hexes,
                                        const VertexConstraints& constraints, const std::vector<double>& sj,
                                        double threshold = 0.3);

}  // namespace dualhex::mesher

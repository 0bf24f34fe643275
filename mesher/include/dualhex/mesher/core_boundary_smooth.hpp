#pragma once
// Stage "core boundary smoothing" (run by the pipeline right before pad): the core's
// boundary made padding-friendly by smoothing away its staircase.
//
// Input : the core (points (N, 3), hexes (M, 8) VTK order) with a closed boundary,
//         `iterations`, a quality floor.
// Output: the core with its boundary vertices moved (ids, hexes and interior points
//         unchanged); returns the number of accepted vertex moves.
// Why (measured with mesher/pad_diagnosis.hpp, bench/mesh_pad_diagnose): the core chosen
// from the dual is a staircase, so nearly every pad hex sits on a fold of the core
// boundary (a convex and a concave 90-degree turn within one quad: on the bunny 1960 and
// 1811 of the 2077 pad hexes below 0.3 after the pad) and its outer points, on the
// smooth surface, cannot line up with the folded base. Smoothing the core boundary first
// (as octree codes smooth the core/buffer interface before projecting, e.g. Marechal
// 2009; Gao et al. 2019 smooth the padded mesh globally) turns the base quads towards
// the surface, so the pad hexes are nearly prisms of the surface.
// Method: Gauss-Seidel sweeps in id order over the boundary vertices: each moves towards
// the mean of its boundary-edge neighbours (factor 0.5, else 0.25), taken only where no
// hex at the vertex ends below min(floor, its scaled Jacobian before) — so no core hex
// becomes inverted or drops below the floor. Deterministic.
#include <cstddef>

#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::mesher {

std::size_t smooth_core_boundary(geometry::HexMesh& core, int iterations, double floor = 0.5);

}  // namespace dualhex::mesher

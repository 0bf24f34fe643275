#pragma once
// Stage "smooth": Laplacian smoothing of the interior vertices that never adds inverted hexes.
#include <vector>

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/quality_state.hpp"

namespace dualhex::mesher {

/// In: the mesh, its boundary flags (points), `iterations`, its current quality state.
/// Each iteration moves every interior vertex with neighbours to the mean of its hex-edge
/// neighbours; an iteration that increases the number of inverted hexes is undone and
/// ends the stage. Out: the mesh and `state` after the accepted iterations; returns their
/// number.
int smooth_interior(geometry::HexMesh& mesh, const std::vector<char>& on_boundary, int iterations, QualityState& state);

}  // namespace dualhex::mesher

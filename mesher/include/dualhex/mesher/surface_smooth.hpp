#pragma once
// Stage "smooth", surface part: tangential Laplacian smoothing of the Surface vertices
// over the boundary quads, each result put back on the surface (its closest point).
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/constrained_position.hpp"
#include "dualhex/mesher/quality_state.hpp"

namespace dualhex::mesher {

/// In: the mesh, its domain (roles: only Surface vertices move), `iterations`, its quality
/// state. Each iteration visits every Surface vertex (Gauss-Seidel) and moves it half-way
/// to the mean of its boundary-edge neighbours, in the tangent plane, then onto the
/// surface; a move that increases the number of inverted hexes at the vertex is refused,
/// so the inverted count never grows. Stops early when an iteration moves nothing. Out:
/// mesh and state; returns the iterations done.
int smooth_surface(geometry::HexMesh& mesh, const VertexDomain& domain, int iterations, QualityState& state);

}  // namespace dualhex::mesher

#pragma once
// Stage "smooth", surface part: tangential Laplacian smoothing of the Surface vertices
// over the boundary quads, each result put back on the surface (its closest point).
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/constrained_position.hpp"
#include "dualhex/mesher/quality_state.hpp"

namespace dualhex::mesher {

/// In: the mesh, its domain (roles: only Surface vertices move), `iterations`, its quality
/// state. Each iteration moves every Surface vertex half-way to the mean of its
/// boundary-edge neighbours, in the tangent plane, then onto the surface; an iteration
/// that increases the inverted count is undone and ends the stage. Out: mesh and state
/// after the accepted iterations; returns their number.
int smooth_surface(geometry::HexMesh& mesh, const VertexDomain& domain, int iterations, QualityState& state);

}  // namespace dualhex::mesher

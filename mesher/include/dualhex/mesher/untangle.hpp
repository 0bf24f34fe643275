#pragma once
// Stage "untangle": pull the vertices of bad hexes back towards their unprojected positions.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/quality_state.hpp"

namespace dualhex::mesher {

/// In: the mesh, its points before projection (points), the rounds and the threshold, its
/// quality state. A round moves every vertex of a hex that is inverted or below `below`
/// half-way back to its unprojected position; a round that increases the inverted count,
/// or keeps it and increases the count below the threshold, is undone and ends the stage
/// (trading surface distance for quality). Out: mesh and state after the accepted rounds;
/// returns the vertex moves made (summed over rounds).
std::size_t untangle_towards(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& unprojected, int rounds,
                             double below, QualityState& state);

}  // namespace dualhex::mesher

#pragma once
// Stage "restore" (after untangle): the untangle stage knows no vertex roles and pulls the
// vertices of bad hexes, snapped ones included, back towards the dual, undoing creases.
// This stage moves each Curve/Corner vertex back towards where the features stage put it
// wherever that costs no quality: a move (all the way, else half-way) is kept iff no hex
// around the vertex becomes inverted and none drops below `below` that was not already.
// Until an optimiser that honours the roles replaces untangle.
//
// In : the mesh, the positions the features stage gave (points), the constraints, the
//      quality threshold, the rounds, the quality state. Out: mesh and state updated;
//      returns the moves kept (summed over rounds). Only points change.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/quality_state.hpp"
#include "dualhex/mesher/vertex_constraints.hpp"

namespace dualhex::mesher {

/// Throws std::invalid_argument if targets or constraints do not match the mesh.
std::size_t restore_features(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& targets,
                             const VertexConstraints& constraints, double below, int rounds, QualityState& state);

}  // namespace dualhex::mesher

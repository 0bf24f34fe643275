#pragma once
// The last step of the features stage: after snap_features has laid the hex creases onto
// the input's feature curves, a boundary vertex next to a crease may still sit on the
// patch across it (projection picked the nearer face). Such Surface vertices go onto the
// patch on their own side of the crease.
//
// In : the mesh and constraints as snap_features left them, its report's path edges, the
//      surface's tree and its FeatureSet (patches, curve sides: geometry/feature_curves.hpp).
// Out: Surface vertices moved (only points change); returns how many.
//
// Sides by orientation, not distance: a boundary quad (outward, counter-clockwise) that
// walks a path edge in the curve's direction lies on the curve's left, else on its right,
// and wants that side's patch. Boundary regions are the quads joined across non-path
// edges; a region whose path-side quads all want one patch wants it everywhere (a curve
// left unsnapped merges two regions: then only its path-side quads decide). A Surface
// vertex whose quads want one patch, other than the patch of its closest triangle, moves
// to the closest point of the wanted patch.
#include <cstddef>
#include <vector>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/feature_curves.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/features.hpp"
#include "dualhex/mesher/vertex_constraints.hpp"

namespace dualhex::mesher {

/// Throws std::invalid_argument if the FeatureSet's patches do not match the tree's surface,
/// the constraints not the mesh, or a path edge names a curve or vertex out of range.
std::size_t project_to_patches(geometry::HexMesh& mesh, const geometry::AabbTree& tree,
                               const geometry::FeatureSet& features, const VertexConstraints& constraints,
                               const std::vector<PathEdge>& path_edges);

}  // namespace dualhex::mesher

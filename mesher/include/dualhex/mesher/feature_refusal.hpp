#pragma once
// The last step of the features stage: the stage refuses snaps that invert hexes it cannot
// repair, so it never hands on a hex it inverted (validity before creases).
//
// In : the mesh as snap_features and project_to_patches left it, the points and per-hex
//      scaled Jacobians from before the snap, the constraints and report the snap produced,
//      the surface's tree and the moving stages' feature curves (constrained_position.hpp).
// Out: the mesh and constraints with every hex the snap inverted either repaired or
//      un-snapped; the report's counts and path edges updated; the quality state current.
//
// Method: 1) repair: the optimiser (optimise.hpp) with a target just above 0 on the region
// within `repair_rings` vertex rings of the hexes the snap inverted, taken as a mesh of its
// own whose vertices on hexes outside it are held, every snapped vertex on its corner or
// curve: local, so it costs little and changes nothing elsewhere; 2) undo, repeated until no hex is inverted that was not
// before the snap: for each such hex, its corner and curve vertices are given up (back
// where they were, role Surface; the rest of their curve stays snapped, so one bad spot
// does not cost a whole crease), and a hex without snapped vertices has its moved vertices
// put back. Each round restores at
// least one vertex (a hex whose 8 vertices are all back is as it was, not inverted), so it
// ends. Deterministic: hexes and curves in id order.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/constrained_position.hpp"
#include "dualhex/mesher/features.hpp"
#include "dualhex/mesher/quality_state.hpp"
#include "dualhex/mesher/vertex_constraints.hpp"

namespace dualhex::mesher {

struct FeatureRefusalOptions {
    /// The repair's optimiser budget (optimise.hpp work_per_vertex, of the repaired region's
    /// vertices); 0: no repair, undo only.
    double repair_work_per_vertex = 20;
    int repair_rings = 2;  ///< the region: the inverted hexes grown by this many vertex rings
};

/// Throws std::invalid_argument if `before` or `sj_before` do not match the mesh.
void refuse_inverting_snaps(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& before,
                            const std::vector<double>& sj_before, VertexConstraints& constraints,
                            FeatureSnapReport& report, const geometry::AabbTree& tree, const FeatureCurves& curves,
                            QualityState& state, const FeatureRefusalOptions& options = {});

}  // namespace dualhex::mesher

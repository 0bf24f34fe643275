#pragma once
// Stage "features": snap the boundary of a hex mesh onto the sharp features of the input
// (corners and feature curves, geometry/feature_curves.hpp), after the stage that puts the
// boundary vertices on the surface and before the stages that move vertices.
//
// In : a hex mesh (VTK order) whose boundary vertices (vertices of boundary quads = faces of
//      one hex) lie on the input surface, however they got there; the input's FeatureSet;
//      VertexConstraints (points, or empty: then boundary vertices are Surface, the others
//      Interior); options.
// Out: the mesh with vertices moved (topology untouched: only points change), constraints
//      with Corner on the snapped corners and Curve + curve index on the snapped curves'
//      path vertices, and a FeatureSnapReport.
//
// Method (after Gao et al. 2019, "Feature preserving octree-based hexahedral meshing",
// and Marechal 2009, "Advances in octree-based all-hexahedral mesh generation"; our own
// formulation): 1) corners: every (input corner, boundary vertex) pair among each
// corner's nearest candidates, greedily by distance, each vertex and corner used once; a
// corner whose nearest free vertex is farther than `max_corner_move` edge lengths stays
// unsnapped. The vertex moves onto the corner. 2) curves, shortest first: a shortest path
// along boundary edges between the curve's two corner vertices (Dijkstra; an edge costs
// its length times 1 + weight * mean distance of its ends and midpoint to the curve / h,
// h = mean boundary edge length), never through a vertex or edge another curve or corner
// holds, searched in a tube around the curve that widens on failure (3, 12 edge lengths,
// then anywhere); in the two tubes a path may neither take the last free edges of a foreign
// corner that still has curves to come, nor a corner neighbour reserved as another curve's
// exit (each corner's curve ends are matched to its neighbours by direction, the best
// injective match). A curve left without a path goes first in the
// next of 8 passes (rip-up and retry); the pass snapping most curves wins. The path's inner
// vertices move onto the curve (closest points if they come in order along it, else
// spaced by the path's arc length). A closed curve, or one from a corner back to itself,
// is cut in two halves at free vertices nearest to arc 0 and half its length. Curves
// whose corners are unsnapped, or with no path, are left as they are (counted).
#include <cstddef>
#include <vector>

#include "dualhex/geometry/feature_curves.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/vertex_constraints.hpp"

namespace dualhex::mesher {

struct FeatureSnapOptions {
    double path_weight = 10.0;      ///< weight of the distance to the curve in a path edge's cost
    double max_corner_move = 2.0;   ///< in mean boundary edge lengths
    /// Paths take no two edges of one boundary quad in a row where the curve runs straight
    /// (three of its corners on a straight piece of curve make its pad hex flat) unless no
    /// path without is found. Opt-in (`dualhex mesh --feature-path-rule`): on tue_block it
    /// cut such turns 369 -> 66 but doubled the hexes the snap inverted (622 -> 1228) and
    /// raised the share below 0.5 (13.7 -> 15.9 %, mesher/README.md).
    bool one_edge_per_quad = false;
};

/// A boundary edge of a snapped path, from -> to along its curve's direction.
struct PathEdge {
    int from = 0, to = 0;
    int curve = 0;  ///< index into FeatureSet::curves
};

struct FeatureSnapReport {
    std::size_t corners = 0, corners_snapped = 0;
    std::size_t curves = 0, curves_snapped = 0;  ///< curves whose whole path was found
    std::size_t curve_vertices = 0;              ///< vertices given the Curve role
    /// Path vertices whose two path edges lie in one boundary quad where the curve runs straight.
    std::size_t quad_turns = 0;
    std::size_t inverted_before = 0, inverted_after = 0;  ///< hexes with scaled Jacobian <= 0
    double max_move = 0;                         ///< largest vertex displacement (absolute)
    std::vector<PathEdge> path_edges;            ///< the snapped paths' boundary edges
    std::size_t patch_moves = 0;                 ///< left 0 here; the pipeline: project_to_patches' count
    /// Left 0 here; refuse_inverting_snaps (feature_refusal.hpp) fills them: hexes the snap
    /// inverted, how many of them its repair untangled, corner and curve vertices given up,
    /// points put back.
    std::size_t inverted_by_snap = 0, repaired = 0;
    std::size_t corners_undone = 0, curve_vertices_undone = 0, vertices_restored = 0;
};

/// Throws std::invalid_argument if constraints are neither empty nor of the mesh's size, or
/// for negative options.
FeatureSnapReport snap_features(geometry::HexMesh& mesh, const geometry::FeatureSet& features,
                                VertexConstraints& constraints, const FeatureSnapOptions& options = {});

}  // namespace dualhex::mesher

#pragma once
// The clipped dual: the dual hex mesh of a complex filling an axis-aligned box, with the
// boundary cells KEPT, so that the hexes fill the whole box. One hex per primal vertex,
// boundary vertices included. Exact: no floating point (dual vertex positions are rational
// centroids; a writer converts them).
//
// Why extra dual vertices. The dual cell of an interior vertex v has the cells around v as
// its 8 vertices (interior_dual, dual.hpp). A vertex on the box surface has fewer cells:
// reflect the complex across the box plane(s) through v and v becomes interior, its dual
// cell a cube made of the cells on both sides; the box plane cuts that cube into two
// mirror halves. The half on our side is v's clipped dual cell; it is a cube itself, whose
// vertices where the mirror plane cuts the full cube are
//   - a boundary face at v (its dual edge, cell -> mirrored cell, crosses the plane at the
//     face: the dual vertex sits on the face),
//   - a crease edge at v (a boundary edge on a box edge: two boundary faces in different
//     axis planes; with two mirror planes the dual face of that edge is cut there),
//   - v itself if it is a box corner (three mirror planes: the cube's corner at v).
// So the dual vertices are: every cell, every boundary face, every crease edge, every
// corner vertex. The dual cell of v is built from the cells, boundary faces and crease
// edges at v and v itself if it is a corner; its 6 faces are
//   - one per edge e = (v, w) at v: the cells around e in order, closed on the surface by
//     e's two boundary faces (and, on a crease, e's crease vertex between them);
//   - one per box plane through v (a "cap" on the box surface): the boundary faces of that
//     plane around v, closed by the crease edges (and the corner) at v in that plane.
// Counting: an interior vertex has 6 edges, 0 planes; a face vertex 5 edges (4 on the
// surface), 1 plane; a crease vertex 4 edges, 2 planes; a corner 3 edges, 3 planes: 6 faces
// in every case, and the dual cell must be a combinatorial cube (8 vertices, 12 edges,
// 6 quads, every vertex of degree 3, connected) — checked on the constructed cell, never
// inferred. The interior dual edges are then exactly the duals of ALL primal faces (cell to
// cell, or cell to boundary face), so their valence histogram is the primal face-size
// histogram.
//
// Orientation (VTK_HEXAHEDRON). Each dual face loop is built with its right-hand normal
// pointing out of v's dual cell: the cells around e = (v, w) counter-clockwise about
// v -> w (a cell leaves through its half-face walking v -> w), a cap counter-clockwise
// seen from outside the box (the boundary faces' outward loops give the turning sense).
// The cube check requires every dual edge to be walked once in each direction by the two
// faces sharing it (a consistently oriented sphere). hex[0..3] is the first face reversed
// (right-hand normal into the hex; for an interior vertex the cells around its first edge
// clockwise about v -> w, as dual_hex does), hex[i + 4] the remaining neighbour of hex[i].
// With dual vertices inside their primal entities this is the positively oriented order
// (tested exactly on boxes of hexes).
//
// The box is the bounding box of the complex's positions unless given. Boundary faces
// (one cell) must lie in a box plane; one that does not (a hole) makes the dual cells of
// its vertices fail with a message, as does any vertex whose dual cell is not a cube.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex {

/// An exact rational point: sum / denominator (sum of the lattice positions of the primal
/// entity's distinct vertices, denominator their number).
struct RationalPoint {
    LatticePoint sum;
    std::int64_t denominator = 1;
    /// Coordinate `axis` as a double, divided by `scale` (writer use only).
    [[nodiscard]] double coordinate(int axis, double scale = 1.0) const {
        return static_cast<double>(sum[axis]) / (static_cast<double>(denominator) * scale);
    }
};

enum class DualVertexKind : std::uint8_t { Cell, BoundaryFace, CreaseEdge, Corner };

struct ClippedDual {
    /// Dual vertices: first all cells (dual vertex c = cell c), then boundary faces, crease
    /// edges, corner vertices. kind[i] and primal[i] (index of the cell/face/edge/vertex).
    std::vector<RationalPoint> points;
    std::vector<DualVertexKind> kind;
    std::vector<std::uint32_t> primal;
    /// Hexes in VTK_HEXAHEDRON order over dual vertex indices, one per primal vertex whose
    /// clipped dual cell is a cube (primal_vertex[h] is hex h's vertex).
    std::vector<std::array<std::uint32_t, 8>> hexes;
    std::vector<VertexHandle> primal_vertex;
    /// Vertices whose clipped dual cell is not a cube, with the first reason.
    std::vector<DualError> errors;
    LatticePoint box_min, box_max;

    [[nodiscard]] bool all_cubes() const { return errors.empty(); }
    [[nodiscard]] std::size_t n_points() const { return points.size(); }
};

/// The clipped dual of a complex filling the box [box_min, box_max].
[[nodiscard]] ClippedDual clipped_dual(const CellComplex& complex, const Incidence& incidence,
                                       const LatticePoint& box_min, const LatticePoint& box_max);
/// Same, the box being the bounding box of the positions.
[[nodiscard]] ClippedDual clipped_dual(const CellComplex& complex, const Incidence& incidence);
[[nodiscard]] ClippedDual clipped_dual(const CellComplex& complex);

/// Dual edge valences (number of hexes around each dual edge) over the interior dual edges
/// (those with at least one cell endpoint; the others lie on the box surface). For a valid
/// clipped dual this equals the primal face-size histogram.
[[nodiscard]] std::map<int, std::size_t> clipped_dual_edge_valences(const ClippedDual& dual);

}  // namespace dualhex

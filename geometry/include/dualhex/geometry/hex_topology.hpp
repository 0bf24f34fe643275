#pragma once
// Exact topology checks of an all-hex mesh (issue 12, part 4): on integer vertex ids
// only, never on coordinates (coordinates are used for the scaled Jacobian and to locate
// defects in messages).
//
// Stage  : after extraction / before writing (mesher "check output" stage).
// Input  : hexes — (M, 8) vertex ids in VTK_HEXAHEDRON order; the vertex count N (ids
//          must lie in [0, N), else std::invalid_argument naming the hex and corner).
//          check_hex_topology also takes the points (N, 3) of a HexMesh.
// Output : boundary_defects — the boundary quads (faces of exactly one hex, outward)
//          and every defect of the boundary surface, as vertex ids;
//          check_hex_topology — HexTopology: counts, the first few defects with
//          coordinates, face-connected hex components, boundary components with their
//          Euler characteristic V - E + F, inverted hexes (scaled Jacobian <= 0);
//          surface_topology — components and Euler characteristic of a triangle surface;
//          compare_topology — does the mesh boundary have the surface's topology.
//
// VTK_HEXAHEDRON corners and the outward faces used here (right-hand rule: the normal
// of a face, by its corner order, points out of the hex):
//
//          7-----------6          face 0: 0 3 2 1  (bottom, z-)
//         /|          /|          face 1: 4 5 6 7  (top,    z+)
//        / |         / |          face 2: 0 1 5 4  (front,  y-)
//       4-----------5  |          face 3: 1 2 6 5  (right,  x+)
//       |  3--------|--2          face 4: 2 3 7 6  (back,   y+)
//       | /         | /           face 5: 3 0 4 7  (left,   x-)
//       |/          |/
//       0-----------1     z up, x to the right, y into the page
//
// Definitions (all exact):
// - a boundary edge is an edge of a boundary quad; it is manifold iff it lies in exactly
//   2 boundary quads, and oriented iff those two traverse it in opposite directions;
// - a boundary vertex is manifold iff its link in the boundary quads (a graph on the
//   vertices sharing a boundary edge with it, one arc per quad corner at it) is one
//   simple cycle: every link vertex has degree 2 and the link is connected. So a vertex
//   of a non-manifold edge is a non-manifold vertex too, and two solids touching at a
//   vertex only give a link of two cycles;
// - a face in 3 or more hexes, or an interior face both of whose hexes traverse it in
//   the same direction (overlapping or mis-ordered hexes), is reported as a face defect;
// - hex components: classes of hexes under "share a face" (all 4 ids);
// - boundary components: classes of boundary quads under "share a vertex"; per class
//   V, E, F are its vertices, edges and quads, chi = V - E + F (2 for a sphere, 0 for a
//   torus, 2 - 2g for genus g).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/geometry/surface.hpp"

namespace dualhex::geometry {

/// The 6 faces of a VTK hex, outward (see the diagram).
inline constexpr std::array<std::array<int, 4>, 6> kHexFaces{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
/// The 12 edges of a VTK hex: bottom ring, top ring, verticals.
inline constexpr std::array<std::array<int, 2>, 12> kHexEdgeCorners{
    {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

/// A boundary edge (a < b) in `quads` != 2 boundary quads.
struct EdgeDefect {
    int a = 0, b = 0;
    int quads = 0;
};

/// A face (corner ids as in its first hex) used by `hexes` hexes; `same_direction` if
/// used by 2 hexes that traverse it the same way.
struct FaceDefect {
    std::array<int, 4> corners{};
    int hexes = 0;
};

/// Exact boundary structure of a set of hexes (every defect listed, ids sorted).
struct BoundaryDefects {
    std::vector<std::array<int, 4>> quads;  ///< boundary quads, outward, in key order
    std::size_t boundary_edges = 0;
    std::size_t boundary_vertices = 0;
    std::vector<EdgeDefect> non_manifold_edges;         ///< in != 2 boundary quads
    std::vector<std::array<int, 2>> misoriented_edges;  ///< 2 quads, same direction
    std::vector<int> non_manifold_vertices;             ///< link not one cycle
    std::vector<FaceDefect> face_defects;               ///< in >= 3 hexes, or 2 same direction
    std::vector<std::size_t> degenerate_hexes;          ///< a vertex id repeated in the hex
    [[nodiscard]] bool manifold() const {
        return non_manifold_edges.empty() && misoriented_edges.empty() && non_manifold_vertices.empty() &&
               face_defects.empty() && degenerate_hexes.empty();
    }
};

/// The boundary quads and all boundary defects of `hexes` (ids in [0, vertex_count)).
[[nodiscard]] BoundaryDefects boundary_defects(const std::vector<std::array<int, 8>>& hexes, std::size_t vertex_count);

/// One connected piece of a quad or triangle surface and its Euler characteristic.
struct SurfaceComponent {
    std::size_t vertices = 0, edges = 0, faces = 0;
    [[nodiscard]] std::int64_t euler() const {
        return static_cast<std::int64_t>(vertices) - static_cast<std::int64_t>(edges) +
               static_cast<std::int64_t>(faces);
    }
};

/// A defect's place: its vertex ids and their coordinates.
struct DefectLocation {
    std::vector<int> vertices;
    std::vector<Eigen::Vector3d> points;
    int count = 0;                               ///< edges: boundary quads at it; faces: hexes at it; else 0
    [[nodiscard]] std::string describe() const;  ///< "vertices 3-7 at (0 0 1)-(1 0 1) (4 quads)"
};

struct HexTopology {
    std::size_t hexes = 0, boundary_quads = 0, boundary_edges = 0, boundary_vertices = 0;
    std::size_t non_manifold_edges = 0, misoriented_edges = 0, non_manifold_vertices = 0;
    std::size_t face_defects = 0, degenerate_hexes = 0, inverted_hexes = 0;
    std::size_t hex_components = 0;
    std::vector<std::size_t> hexes_per_component;       ///< decreasing
    std::vector<SurfaceComponent> boundary_components;  ///< by decreasing face count
    /// The first `max_listed` of each kind (inverted: one vertex list per hex, its 8 ids).
    std::vector<DefectLocation> first_non_manifold_edges, first_misoriented_edges, first_non_manifold_vertices,
        first_face_defects, first_inverted_hexes;
    /// Boundary edge- and vertex-manifold, consistently oriented, no face defect, no
    /// degenerate or inverted hex.
    [[nodiscard]] bool valid() const {
        return non_manifold_edges == 0 && misoriented_edges == 0 && non_manifold_vertices == 0 && face_defects == 0 &&
               degenerate_hexes == 0 && inverted_hexes == 0;
    }
    /// Multi-line human-readable summary (counts, then the listed defects).
    [[nodiscard]] std::string summary() const;
};

/// All checks on a HexMesh. Throws std::invalid_argument for an id out of range.
[[nodiscard]] HexTopology check_hex_topology(const HexMesh& mesh, std::size_t max_listed = 5);

/// Components of a triangle surface (classes of triangles under "share a vertex") and
/// V - E + F of each, by decreasing face count. Exact, on indices; throws
/// std::invalid_argument for an index out of range.
[[nodiscard]] std::vector<SurfaceComponent> surface_topology(const TriangleSurface& surface);

struct TopologyComparison {
    bool same = false;                     ///< same number of components, same chi multiset
    std::vector<std::int64_t> mesh_euler;  ///< sorted decreasingly
    std::vector<std::int64_t> surface_euler;
    [[nodiscard]] std::string describe() const;  ///< "boundary chi {2, 0} vs surface chi {0}"
};
[[nodiscard]] TopologyComparison compare_topology(const std::vector<SurfaceComponent>& mesh_boundary,
                                                  const std::vector<SurfaceComponent>& surface);
/// The mesh's boundary components against those of the surface it should match.
[[nodiscard]] TopologyComparison compare_topology(const HexTopology& mesh, const TriangleSurface& surface);

}  // namespace dualhex::geometry

#pragma once
// The link of a vertex v as a small explicit 2-complex:
//   link vertices = edges incident to v,
//   link edges    = corners of faces at v (the two face edges meeting at v),
//   link faces    = corners of cells at v (the cell's face corners at v, chained into a
//                   cycle of link vertices, in the order induced by the cell's outward
//                   orientation).
// For an interior vertex of a valid hex-dual-able complex the link is an octahedron.
#include <array>
#include <vector>

#include "dualhex/topology/incidence.hpp"

namespace dualhex {

struct VertexLink {
    VertexHandle center;
    std::vector<EdgeHandle> vertices;            // link vertex i <-> incident edge
    std::vector<std::array<int, 2>> edges;       // link edge <-> face corner (link vertex ids)
    std::vector<FaceHandle> edge_faces;          // the face of each link edge
    std::vector<std::vector<int>> faces;         // link face <-> cell corner (cycle of link vertex ids)
    std::vector<CellHandle> face_cells;          // the cell of each link face
    int broken_cell_corners = 0;                 // cell corners that are not a single cycle

    /// Every link edge distinct and in exactly two link faces, every link face a cycle of
    /// link edges, no broken corners, connected.
    [[nodiscard]] bool is_closed_connected_surface() const;
    /// 6 vertices, 12 edges, 8 triangles, and a closed connected surface.
    [[nodiscard]] bool is_octahedron() const;
};

/// Builds the link of v. Never throws on invalid topology: defects show up as counts.
[[nodiscard]] VertexLink vertex_link(const CellComplex& complex, const Incidence& incidence, VertexHandle v);

}  // namespace dualhex

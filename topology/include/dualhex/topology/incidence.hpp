#pragma once
// Incidence: every "which X touch this Y" relation of a CellComplex, as CSR arrays.
// Derived and disposable: build it when needed, drop it when the complex changes.
//
// Lists are deduplicated per entity (a face using a vertex twice lists it once), except
// face -> cells, which keeps one entry per cell half-face referencing the face, so that a
// face used by 3 cells or twice by one cell can be reported. face_halffaces(f)[i] is the
// half-face through which face_cells(f)[i] uses f.
//
// Boundary: a face is boundary iff it has exactly one incident cell entry; an edge or a
// vertex is boundary iff it lies on a boundary face. Everything else is interior.
//
// Lifetime: an Incidence keeps a pointer to its complex (for find_edge); the complex must
// outlive it.
#include <span>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/csr.hpp"

namespace dualhex {

class Incidence {
public:
    explicit Incidence(const CellComplex& complex);

    [[nodiscard]] std::span<const EdgeHandle> vertex_edges(VertexHandle v) const { return vertex_edges_[v.index()]; }
    [[nodiscard]] std::span<const FaceHandle> vertex_faces(VertexHandle v) const { return vertex_faces_[v.index()]; }
    [[nodiscard]] std::span<const CellHandle> vertex_cells(VertexHandle v) const { return vertex_cells_[v.index()]; }
    [[nodiscard]] std::span<const FaceHandle> edge_faces(EdgeHandle e) const { return edge_faces_[e.index()]; }
    [[nodiscard]] std::span<const CellHandle> edge_cells(EdgeHandle e) const { return edge_cells_[e.index()]; }
    [[nodiscard]] std::span<const CellHandle> face_cells(FaceHandle f) const { return face_cells_[f.index()]; }
    [[nodiscard]] std::span<const HalfFaceHandle> face_halffaces(FaceHandle f) const { return face_halffaces_[f.index()]; }

    [[nodiscard]] bool is_boundary(FaceHandle f) const { return face_cells(f).size() == 1; }
    [[nodiscard]] bool is_boundary(EdgeHandle e) const { return edge_boundary_[e.index()] != 0; }
    [[nodiscard]] bool is_boundary(VertexHandle v) const { return vertex_boundary_[v.index()] != 0; }

    /// The edge joining a and b, or an invalid handle.
    [[nodiscard]] EdgeHandle find_edge(VertexHandle a, VertexHandle b) const;
    /// The other cell of a face with exactly two cell entries, or an invalid handle.
    [[nodiscard]] CellHandle other_cell(FaceHandle f, CellHandle c) const;

private:
    const CellComplex* complex_;
    Csr<EdgeHandle> vertex_edges_;
    Csr<FaceHandle> vertex_faces_;
    Csr<CellHandle> vertex_cells_;
    Csr<FaceHandle> edge_faces_;
    Csr<CellHandle> edge_cells_;
    Csr<CellHandle> face_cells_;
    Csr<HalfFaceHandle> face_halffaces_;
    std::vector<char> edge_boundary_, vertex_boundary_;
};

}  // namespace dualhex

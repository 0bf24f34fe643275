#pragma once
// CellComplex: an exact, combinatorial polyhedral cell complex (DESIGN.md section 3).
//
// Storage (flat arrays, ultimaille-like):
//   - vertices: an exact LatticePoint each (the key used for welding and output);
//   - faces: CSR vertex loops; face_edges(f)[i] is the edge from loop[i] to loop[i+1];
//   - cells: CSR lists of HalfFaceHandle;
//   - edges: derived at construction, the unique unordered vertex pairs appearing
//     consecutively in some face loop (numbered by smaller endpoint, then by
//     first appearance).
//
// Orientation convention: a cell lists each of its faces as the half-face whose vertex
// loop is counter-clockwise seen from outside the cell, i.e. whose right-hand-rule
// normal points out of the cell. Two cells sharing a face therefore use opposite sides.
//
// The complex is immutable; adjacency (Incidence) is derived from it and disposable.
// Invalid topology (repeated vertices, open cells, ...) is representable on purpose, so
// that `validate` can report it; only out-of-range handles are rejected.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "dualhex/topology/handles.hpp"
#include "dualhex/topology/lattice.hpp"

namespace dualhex {

class CellComplex {
public:
    CellComplex() = default;

    /// Raw construction. Inputs:
    ///   positions      one lattice point per vertex
    ///   face_offsets   CSR offsets into face_loops (size n_faces + 1, starting at 0)
    ///   face_loops     vertex loops of all faces, concatenated
    ///   cell_offsets   CSR offsets into cell_halffaces (size n_cells + 1, starting at 0)
    ///   cell_halffaces outward half-faces of all cells, concatenated
    /// Throws std::invalid_argument on malformed offsets, an empty face loop, or a handle
    /// out of range. Edges are derived here.
    CellComplex(std::vector<LatticePoint> positions, std::vector<std::uint32_t> face_offsets,
                std::vector<VertexHandle> face_loops, std::vector<std::uint32_t> cell_offsets,
                std::vector<HalfFaceHandle> cell_halffaces);

    [[nodiscard]] std::size_t n_vertices() const { return positions_.size(); }
    [[nodiscard]] std::size_t n_edges() const { return edge_vertices_.size(); }
    [[nodiscard]] std::size_t n_faces() const { return face_offsets_.size() - 1; }
    [[nodiscard]] std::size_t n_cells() const { return cell_offsets_.size() - 1; }

    [[nodiscard]] const LatticePoint& position(VertexHandle v) const { return positions_[v.index()]; }
    /// Endpoints (smaller vertex id first).
    [[nodiscard]] const std::array<VertexHandle, 2>& edge_vertices(EdgeHandle e) const {
        return edge_vertices_[e.index()];
    }
    /// The stored loop (= the loop of half-face side 0).
    [[nodiscard]] std::span<const VertexHandle> face_vertices(FaceHandle f) const {
        return {face_loops_.data() + face_offsets_[f.index()], face_loops_.data() + face_offsets_[f.index() + 1]};
    }
    /// face_edges(f)[i] joins face_vertices(f)[i] and face_vertices(f)[i+1 mod n].
    [[nodiscard]] std::span<const EdgeHandle> face_edges(FaceHandle f) const {
        return {face_edges_.data() + face_offsets_[f.index()], face_edges_.data() + face_offsets_[f.index() + 1]};
    }
    /// The loop in the half-face's orientation (side 1: the stored loop reversed, starting
    /// at the same first vertex).
    [[nodiscard]] std::vector<VertexHandle> halfface_vertices(HalfFaceHandle h) const;
    [[nodiscard]] std::span<const HalfFaceHandle> cell_halffaces(CellHandle c) const {
        return {cell_halffaces_.data() + cell_offsets_[c.index()],
                cell_halffaces_.data() + cell_offsets_[c.index() + 1]};
    }

    /// Raw arrays (for copying/transforming a complex without going through a builder).
    [[nodiscard]] const std::vector<LatticePoint>& positions() const { return positions_; }
    [[nodiscard]] const std::vector<std::uint32_t>& face_offsets() const { return face_offsets_; }
    [[nodiscard]] const std::vector<VertexHandle>& face_loops() const { return face_loops_; }
    [[nodiscard]] const std::vector<std::uint32_t>& cell_offsets() const { return cell_offsets_; }
    [[nodiscard]] const std::vector<HalfFaceHandle>& all_cell_halffaces() const { return cell_halffaces_; }

private:
    void derive_edges();

    std::vector<LatticePoint> positions_;
    std::vector<std::uint32_t> face_offsets_{0};
    std::vector<VertexHandle> face_loops_;
    std::vector<EdgeHandle> face_edges_;  // parallel to face_loops_
    std::vector<std::uint32_t> cell_offsets_{0};
    std::vector<HalfFaceHandle> cell_halffaces_;
    std::vector<std::array<VertexHandle, 2>> edge_vertices_;
};

}  // namespace dualhex

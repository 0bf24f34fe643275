#pragma once
// ComplexBuilder: assembles a CellComplex from lattice points, vertex loops and cells,
// welding everything by exact keys.
//   - add_vertex: one vertex per distinct LatticePoint;
//   - add_face: one face per distinct cyclic vertex sequence, up to rotation AND reversal;
//     the returned half-face has the orientation of the given loop (side 0 if it runs like
//     the stored loop, side 1 if reversed);
//   - add_cell: a list of outward half-faces (see cell_complex.hpp for the convention).
// Hashing uses flat open-addressing tables over the builder's own arrays, so adding a face
// does not allocate per face. Malformed input that cannot even be stored (an empty loop,
// an unknown handle) throws std::invalid_argument; everything else is stored as given and
// left for `validate` to judge.
#include <span>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/id_hash_table.hpp"

namespace dualhex {

class ComplexBuilder {
public:
    ComplexBuilder() = default;
    /// Pre-sizes the arrays (optional, for speed).
    void reserve(std::size_t n_vertices, std::size_t n_faces, std::size_t n_cells) {
        reserve(n_vertices, n_faces, n_cells, n_vertices);
    }
    /// Same, with room in the welding table for only `n_welded` of the vertices (the rest
    /// being added with add_vertex_unwelded).
    void reserve(std::size_t n_vertices, std::size_t n_faces, std::size_t n_cells, std::size_t n_welded);

    /// The vertex at `p`, created if new.
    VertexHandle add_vertex(const LatticePoint& p);
    /// A new vertex at `p`, NOT welded: no lookup, and add_vertex / find_vertex will never
    /// see it. For callers that weld a set of points themselves (e.g. by an array index of
    /// grid corners) and guarantee that no point of that set ever reaches add_vertex.
    VertexHandle add_vertex_unwelded(const LatticePoint& p) {
        positions_.push_back(p);
        return VertexHandle(positions_.size() - 1);
    }
    /// The vertex at `p`, or an invalid handle.
    [[nodiscard]] VertexHandle find_vertex(const LatticePoint& p) const;

    /// The half-face with this loop's orientation; the face is created if no face with the
    /// same cyclic sequence (in either direction) exists yet.
    HalfFaceHandle add_face(std::span<const VertexHandle> loop);
    HalfFaceHandle add_face(std::initializer_list<VertexHandle> loop) {
        return add_face(std::span<const VertexHandle>(loop.begin(), loop.size()));
    }
    /// A new cell with these outward half-faces (no dedupe: adding a cell twice is an
    /// error `validate` reports).
    CellHandle add_cell(std::span<const HalfFaceHandle> halffaces);
    /// Convenience: each loop a face of the cell, counter-clockwise seen from outside.
    CellHandle add_cell_from_loops(const std::vector<std::vector<LatticePoint>>& loops);

    [[nodiscard]] std::size_t n_vertices() const { return positions_.size(); }
    [[nodiscard]] std::size_t n_faces() const { return face_offsets_.size() - 1; }
    [[nodiscard]] std::size_t n_cells() const { return cell_offsets_.size() - 1; }

    /// The arrays built so far (for callers that merge several builders' parts).
    [[nodiscard]] const std::vector<LatticePoint>& positions() const { return positions_; }
    [[nodiscard]] const std::vector<std::uint32_t>& face_offsets() const { return face_offsets_; }
    [[nodiscard]] const std::vector<VertexHandle>& face_loops() const { return face_loops_; }
    [[nodiscard]] const std::vector<std::uint32_t>& cell_offsets() const { return cell_offsets_; }
    [[nodiscard]] const std::vector<HalfFaceHandle>& cell_halffaces() const { return cell_halffaces_; }

    /// The complex built so far (the builder stays usable).
    [[nodiscard]] CellComplex build() const&;
    /// The complex, moving the arrays out (the builder is left empty-ish: do not reuse).
    [[nodiscard]] CellComplex build() &&;

    /// The arrays as built, for callers that merge several builders (install's parallel
    /// welding), which free each part as soon as it is merged.
    struct Parts {
        std::vector<LatticePoint> positions;
        std::vector<std::uint32_t> face_offsets;
        std::vector<VertexHandle> face_loops;
        std::vector<std::uint32_t> cell_offsets;
        std::vector<HalfFaceHandle> cell_halffaces;
    };
    /// The arrays moved out (the builder is left empty: do not reuse; its welding tables go
    /// with it, so a caller keeping only the parts keeps none of the tables' memory).
    [[nodiscard]] Parts take_parts() &&;

private:
    std::vector<LatticePoint> positions_;
    std::vector<std::uint32_t> face_offsets_{0};
    std::vector<VertexHandle> face_loops_;
    std::vector<std::uint32_t> cell_offsets_{0};
    std::vector<HalfFaceHandle> cell_halffaces_;
    detail::IdHashTable vertex_table_;
    // Direct-mapped cache of recent welds in front of vertex_table_: neighbouring cells
    // repeat most of their points, and the cache stays in L2 while the table does not.
    struct CachedVertex {
        LatticePoint p;
        std::int32_t id = -1;
    };
    // Sized to the complex (a power of two, about twice the vertices so far, at most
    // kVertexCacheSize) and regrown empty as it grows: a small complex (a window, an element)
    // does not pay for zeroing the full cache. Emptying a cache loses no weld: misses go to
    // vertex_table_.
    static constexpr std::size_t kVertexCacheSize = 4096;
    static constexpr std::size_t kVertexCacheMin = 64;
    std::vector<CachedVertex> vertex_cache_;
    void grow_vertex_cache();
    // Faces keyed by their smallest vertex (the first of the stored loop), see LocalIdTable.
    detail::LocalIdTable face_table_;
    std::vector<VertexHandle> scratch_;
    std::vector<HalfFaceHandle> cell_scratch_;
};

}  // namespace dualhex

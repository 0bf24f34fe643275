#include "dualhex/topology/incidence.hpp"

#include <algorithm>
#include <limits>

#include <tbb/parallel_invoke.h>

namespace dualhex {
namespace {

using Row = std::uint32_t;

// Per-row dedupe without hashing: `stamp[item]` remembers the last row that emitted it.
template <class H>
struct Stamper {
    explicit Stamper(std::size_t n) : stamp(n, std::numeric_limits<std::uint32_t>::max()) {}
    bool first(H item, std::size_t row) {
        std::uint32_t& s = stamp[item.index()];
        if (s == static_cast<std::uint32_t>(row)) return false;
        s = static_cast<std::uint32_t>(row);
        return true;
    }
    std::vector<std::uint32_t> stamp;
};

// Rows of one relation are built from (row, item) pairs. One pair buffer per item type is
// reused from relation to relation (cleared, its pages stay mapped: no fresh page faults),
// reserved to an upper bound up front (untouched capacity costs no resident memory,
// regrowth copies do).
template <class T>
using Pairs = std::vector<std::pair<Row, T>>;

// Appends (v, row) for the distinct items of a short list (first occurrence); long lists
// go through the stamper.
template <class H, class T>
void distinct(std::span<const H> items, T row_item, std::size_t row, Stamper<H>& stamper, Pairs<T>& out) {
    const std::size_t n = items.size();
    if (n <= 16) {
        for (std::size_t i = 0; i < n; ++i) {
            bool seen = false;
            for (std::size_t j = 0; j < i && !seen; ++j) seen = items[j] == items[i];
            if (!seen) out.emplace_back(items[i].idx, row_item);
        }
        return;
    }
    for (H item : items)
        if (stamper.first(item, row)) out.emplace_back(item.idx, row_item);
}

}  // namespace

Incidence::Incidence(const CellComplex& k) : complex_(&k) {
    const std::size_t nv = k.n_vertices(), ne = k.n_edges(), nf = k.n_faces(), nc = k.n_cells();
    const std::size_t n_loop = k.face_loops().size(), n_halffaces = k.all_cell_halffaces().size();
    const auto& cell_offsets = k.cell_offsets();
    const auto& halffaces = k.all_cell_halffaces();

    // Two independent groups of relations (each reusing its own pair buffer) are built
    // concurrently; each relation is built exactly as alone, so the result does not depend
    // on the threads.
    const auto by_faces = [&] {
        {
            Pairs<EdgeHandle> ve;
            ve.reserve(2 * ne);
            for (std::size_t e = 0; e < ne; ++e) {
                const auto [a, b] = k.edge_vertices(EdgeHandle(e));
                ve.emplace_back(a.idx, EdgeHandle(e));
                if (b != a) ve.emplace_back(b.idx, EdgeHandle(e));
            }
            vertex_edges_ = Csr<EdgeHandle>::from_pairs(nv, ve);
        }
        Pairs<FaceHandle> vf;  // then edge -> faces
        vf.reserve(n_loop);
        {
            Stamper<VertexHandle> seen(0);
            for (std::size_t f = 0; f < nf; ++f) {
                const FaceHandle fh(f);
                const auto loop = k.face_vertices(fh);
                if (loop.size() > 16 && seen.stamp.empty()) seen = Stamper<VertexHandle>(nv);
                distinct(loop, fh, f, seen, vf);
            }
            vertex_faces_ = Csr<FaceHandle>::from_pairs(nv, vf);
        }
        {
            Pairs<FaceHandle>& ef = vf;
            ef.clear();
            Stamper<EdgeHandle> seen(0);
            for (std::size_t f = 0; f < nf; ++f) {
                const FaceHandle fh(f);
                const auto edges = k.face_edges(fh);
                if (edges.size() > 16 && seen.stamp.empty()) seen = Stamper<EdgeHandle>(ne);
                distinct(edges, fh, f, seen, ef);
            }
            edge_faces_ = Csr<FaceHandle>::from_pairs(ne, ef);
        }
        Pairs<FaceHandle>().swap(vf);
        {
            Pairs<HalfFaceHandle> fh_pairs;
            fh_pairs.reserve(n_halffaces);
            for (HalfFaceHandle h : halffaces) fh_pairs.emplace_back(h.face().idx, h);
            face_halffaces_ = Csr<HalfFaceHandle>::from_pairs(nf, fh_pairs);
        }
    };
    const auto by_cells = [&] {
        // Upper bound of the vertex (edge) references of all cells: the loop sizes of their faces.
        std::size_t cell_refs = 0;
        for (HalfFaceHandle h : halffaces) {
            const auto& fo = k.face_offsets();
            cell_refs += fo[h.face().index() + 1] - fo[h.face().index()];
        }
        Pairs<CellHandle> fc;  // then vertex -> cells, edge -> cells
        fc.reserve(std::max(n_halffaces, cell_refs));
        {
            for (std::size_t c = 0; c < nc; ++c)
                for (std::uint32_t i = cell_offsets[c]; i < cell_offsets[c + 1]; ++i)
                    fc.emplace_back(halffaces[i].face().idx, CellHandle(c));
            face_cells_ = Csr<CellHandle>::from_pairs(nf, fc);
        }
        {
            Pairs<CellHandle>& vc = fc;
            vc.clear();
            Stamper<VertexHandle> in_cell(nv);
            for (std::size_t c = 0; c < nc; ++c) {
                const CellHandle ch(c);
                for (std::uint32_t i = cell_offsets[c]; i < cell_offsets[c + 1]; ++i)
                    for (VertexHandle v : k.face_vertices(halffaces[i].face()))
                        if (in_cell.first(v, c)) vc.emplace_back(v.idx, ch);
            }
            vertex_cells_ = Csr<CellHandle>::from_pairs(nv, vc);
        }
        {
            Pairs<CellHandle>& ec = fc;
            ec.clear();
            Stamper<EdgeHandle> in_cell(ne);
            for (std::size_t c = 0; c < nc; ++c) {
                const CellHandle ch(c);
                for (std::uint32_t i = cell_offsets[c]; i < cell_offsets[c + 1]; ++i)
                    for (EdgeHandle e : k.face_edges(halffaces[i].face()))
                        if (in_cell.first(e, c)) ec.emplace_back(e.idx, ch);
            }
            edge_cells_ = Csr<CellHandle>::from_pairs(ne, ec);
        }
        Pairs<CellHandle>().swap(fc);
    };
    tbb::parallel_invoke(by_faces, by_cells);

    edge_boundary_.assign(ne, 0);
    vertex_boundary_.assign(nv, 0);
    for (std::size_t f = 0; f < nf; ++f) {
        if (!is_boundary(FaceHandle(f))) continue;
        for (VertexHandle v : k.face_vertices(FaceHandle(f))) vertex_boundary_[v.index()] = 1;
        for (EdgeHandle e : k.face_edges(FaceHandle(f))) edge_boundary_[e.index()] = 1;
    }
}

EdgeHandle Incidence::find_edge(VertexHandle a, VertexHandle b) const {
    for (EdgeHandle e : vertex_edges(a)) {
        const auto [p, q] = complex_->edge_vertices(e);
        if ((p == a && q == b) || (p == b && q == a)) return e;
    }
    return {};
}

CellHandle Incidence::other_cell(FaceHandle f, CellHandle c) const {
    const auto cells = face_cells(f);
    if (cells.size() != 2) return {};
    return cells[0] == c ? cells[1] : cells[1] == c ? cells[0] : CellHandle{};
}

}  // namespace dualhex

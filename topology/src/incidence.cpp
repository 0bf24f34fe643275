#include "dualhex/topology/incidence.hpp"

namespace dualhex {
namespace {

using Row = std::uint32_t;

// Per-row dedupe without hashing: `stamp[item]` remembers the last row that emitted it.
template <class H>
struct Stamper {
    explicit Stamper(std::size_t n) : stamp(n, -1) {}
    bool first(H item, std::int64_t row) {
        if (stamp[item.index()] == row) return false;
        stamp[item.index()] = row;
        return true;
    }
    std::vector<std::int64_t> stamp;
};

}  // namespace

Incidence::Incidence(const CellComplex& k) : complex_(&k) {
    const std::size_t nv = k.n_vertices(), ne = k.n_edges(), nf = k.n_faces(), nc = k.n_cells();

    std::vector<std::pair<Row, EdgeHandle>> ve;
    ve.reserve(2 * ne);
    for (std::size_t e = 0; e < ne; ++e) {
        const auto [a, b] = k.edge_vertices(EdgeHandle(e));
        ve.emplace_back(a.idx, EdgeHandle(e));
        if (b != a) ve.emplace_back(b.idx, EdgeHandle(e));
    }
    vertex_edges_ = Csr<EdgeHandle>::from_pairs(nv, ve);

    std::vector<std::pair<Row, FaceHandle>> vf, ef;
    Stamper<VertexHandle> v_seen(nv);
    Stamper<EdgeHandle> e_seen(ne);
    for (std::size_t f = 0; f < nf; ++f) {
        const FaceHandle fh(f);
        for (VertexHandle v : k.face_vertices(fh))
            if (v_seen.first(v, static_cast<std::int64_t>(f))) vf.emplace_back(v.idx, fh);
        for (EdgeHandle e : k.face_edges(fh))
            if (e_seen.first(e, static_cast<std::int64_t>(f))) ef.emplace_back(e.idx, fh);
    }
    vertex_faces_ = Csr<FaceHandle>::from_pairs(nv, vf);
    edge_faces_ = Csr<FaceHandle>::from_pairs(ne, ef);

    std::vector<std::pair<Row, CellHandle>> fc, vc, ec;
    std::vector<std::pair<Row, HalfFaceHandle>> fh_pairs;
    Stamper<VertexHandle> v_in_cell(nv);
    Stamper<EdgeHandle> e_in_cell(ne);
    for (std::size_t c = 0; c < nc; ++c) {
        const CellHandle ch(c);
        const auto row = static_cast<std::int64_t>(c);
        for (HalfFaceHandle h : k.cell_halffaces(ch)) {
            fc.emplace_back(h.face().idx, ch);
            fh_pairs.emplace_back(h.face().idx, h);
            for (VertexHandle v : k.face_vertices(h.face()))
                if (v_in_cell.first(v, row)) vc.emplace_back(v.idx, ch);
            for (EdgeHandle e : k.face_edges(h.face()))
                if (e_in_cell.first(e, row)) ec.emplace_back(e.idx, ch);
        }
    }
    face_cells_ = Csr<CellHandle>::from_pairs(nf, fc);
    face_halffaces_ = Csr<HalfFaceHandle>::from_pairs(nf, fh_pairs);
    vertex_cells_ = Csr<CellHandle>::from_pairs(nv, vc);
    edge_cells_ = Csr<CellHandle>::from_pairs(ne, ec);

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

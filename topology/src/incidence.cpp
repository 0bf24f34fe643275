#include "dualhex/topology/incidence.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <type_traits>

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

// Each relation's rows come from a generator of (row, item) pairs run twice, count then
// place (Csr::from_generator): no pair buffer, which with both groups below at once was
// the largest transient of the whole install + dual (two buffers of 8 bytes per pair).

// Emits (item, row_item) for the distinct items of a short list (first occurrence); long
// lists go through the stamper, made on first need (a new one per pass: its stamps are rows).
template <class H, class T, class Emit>
void distinct(std::span<const H> items, T row_item, std::size_t row, std::size_t n_items, std::optional<Stamper<H>>& stamper,
              Emit& emit) {
    const std::size_t n = items.size();
    if (n <= 16) {
        for (std::size_t i = 0; i < n; ++i) {
            bool seen = false;
            for (std::size_t j = 0; j < i && !seen; ++j) seen = items[j] == items[i];
            if (!seen) emit(static_cast<Row>(items[i].idx), row_item);
        }
        return;
    }
    if (!stamper) stamper.emplace(n_items);
    for (H item : items)
        if (stamper->first(item, row)) emit(static_cast<Row>(item.idx), row_item);
}

}  // namespace

Incidence::Incidence(const CellComplex& k) : complex_(&k) {
    const std::size_t nv = k.n_vertices(), ne = k.n_edges(), nf = k.n_faces(), nc = k.n_cells();
    const auto& cell_offsets = k.cell_offsets();
    const auto& halffaces = k.all_cell_halffaces();

    // Two independent groups of relations are built concurrently; each relation is built
    // exactly as alone, so the result does not depend on the threads.
    const auto by_faces = [&] {
        vertex_edges_ = Csr<EdgeHandle>::from_generator(nv, [&](auto&& emit) {
            for (std::size_t e = 0; e < ne; ++e) {
                const auto [a, b] = k.edge_vertices(EdgeHandle(e));
                emit(static_cast<Row>(a.idx), EdgeHandle(e));
                if (b != a) emit(static_cast<Row>(b.idx), EdgeHandle(e));
            }
        });
        vertex_faces_ = Csr<FaceHandle>::from_generator(nv, [&](auto&& emit) {
            std::optional<Stamper<VertexHandle>> seen;
            for (std::size_t f = 0; f < nf; ++f) distinct(k.face_vertices(FaceHandle(f)), FaceHandle(f), f, nv, seen, emit);
        });
        edge_faces_ = Csr<FaceHandle>::from_generator(ne, [&](auto&& emit) {
            std::optional<Stamper<EdgeHandle>> seen;
            for (std::size_t f = 0; f < nf; ++f) distinct(k.face_edges(FaceHandle(f)), FaceHandle(f), f, ne, seen, emit);
        });
        face_halffaces_ = Csr<HalfFaceHandle>::from_generator(nf, [&](auto&& emit) {
            for (HalfFaceHandle h : halffaces) emit(static_cast<Row>(h.face().idx), h);
        });
    };
    // The faces of cell c, then each face's vertices (edges), deduplicated per cell.
    const auto cell_items = [&](std::size_t n_items, auto&& items_of_face) {
        return [&, n_items, items_of_face](auto&& emit) {
            Stamper<std::remove_cvref_t<decltype(items_of_face(FaceHandle(0))[0])>> in_cell(n_items);
            for (std::size_t c = 0; c < nc; ++c)
                for (std::uint32_t i = cell_offsets[c]; i < cell_offsets[c + 1]; ++i)
                    for (auto item : items_of_face(halffaces[i].face()))
                        if (in_cell.first(item, c)) emit(static_cast<Row>(item.idx), CellHandle(c));
        };
    };
    const auto by_cells = [&] {
        face_cells_ = Csr<CellHandle>::from_generator(nf, [&](auto&& emit) {
            for (std::size_t c = 0; c < nc; ++c)
                for (std::uint32_t i = cell_offsets[c]; i < cell_offsets[c + 1]; ++i)
                    emit(static_cast<Row>(halffaces[i].face().idx), CellHandle(c));
        });
        vertex_cells_ = Csr<CellHandle>::from_generator(nv, cell_items(nv, [&](FaceHandle f) { return k.face_vertices(f); }));
        edge_cells_ = Csr<CellHandle>::from_generator(ne, cell_items(ne, [&](FaceHandle f) { return k.face_edges(f); }));
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

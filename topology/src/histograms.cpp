#include "dualhex/topology/histograms.hpp"

#include <algorithm>

namespace dualhex {

std::map<int, std::size_t> face_size_histogram(const CellComplex& k) {
    std::map<int, std::size_t> h;
    for (std::size_t f = 0; f < k.n_faces(); ++f) ++h[static_cast<int>(k.face_vertices(FaceHandle(f)).size())];
    return h;
}

std::map<int, std::size_t> interior_dual_edge_valence_histogram(const CellComplex& k, const Incidence& inc) {
    std::map<int, std::size_t> h;
    for (std::size_t f = 0; f < k.n_faces(); ++f) {
        const auto loop = k.face_vertices(FaceHandle(f));
        if (std::none_of(loop.begin(), loop.end(), [&](VertexHandle v) { return inc.is_boundary(v); }))
            ++h[static_cast<int>(loop.size())];
    }
    return h;
}

std::map<int, std::size_t> interior_dual_edge_valence_histogram(const CellComplex& k) {
    return interior_dual_edge_valence_histogram(k, Incidence(k));
}

// A cell is a plain hexahedron iff it has 6 faces, all quadrilaterals.
std::size_t non_hex_cell_count(const CellComplex& k) {
    std::size_t n = 0;
    for (std::size_t c = 0; c < k.n_cells(); ++c) {
        const auto hfs = k.cell_halffaces(CellHandle(c));
        bool hex = hfs.size() == 6;
        for (HalfFaceHandle h : hfs) hex = hex && k.face_vertices(h.face()).size() == 4;
        n += hex ? 0 : 1;
    }
    return n;
}

std::int64_t euler_characteristic(const CellComplex& k) {
    return static_cast<std::int64_t>(k.n_vertices()) - static_cast<std::int64_t>(k.n_edges()) +
           static_cast<std::int64_t>(k.n_faces()) - static_cast<std::int64_t>(k.n_cells());
}

}  // namespace dualhex

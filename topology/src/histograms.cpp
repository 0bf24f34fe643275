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

std::int64_t euler_characteristic(const CellComplex& k) {
    return static_cast<std::int64_t>(k.n_vertices()) - static_cast<std::int64_t>(k.n_edges()) +
           static_cast<std::int64_t>(k.n_faces()) - static_cast<std::int64_t>(k.n_cells());
}

}  // namespace dualhex

#include "dualhex/topology/validation.hpp"

#include "checks.hpp"

namespace dualhex {

ValidationReport validate(const CellComplex& k, const ValidationOptions& options) {
    ValidationReport report;
    for (std::size_t f = 0; f < k.n_faces(); ++f) detail::check_face(k, FaceHandle(f), report);
    for (std::size_t c = 0; c < k.n_cells(); ++c) detail::check_cell(k, CellHandle(c), report);
    report.checked_faces = k.n_faces();
    report.checked_cells = k.n_cells();

    const Incidence inc(k);
    for (std::size_t f = 0; f < k.n_faces(); ++f) detail::check_face_conformity(inc, FaceHandle(f), report);
    detail::check_duplicate_cells(k, report);
    if (!options.check_interior) return report;

    auto accepted = [&](VertexHandle v) { return !options.interior_filter || options.interior_filter(v); };
    for (std::size_t i = 0; i < k.n_vertices(); ++i) {
        const VertexHandle v(i);
        if (inc.is_boundary(v) || !accepted(v)) continue;
        ++report.checked_vertices;
        detail::check_interior_vertex(k, inc, v, report);
    }
    for (std::size_t i = 0; i < k.n_edges(); ++i) {
        const EdgeHandle e(i);
        const auto [a, b] = k.edge_vertices(e);
        if (inc.is_boundary(e) || !accepted(a) || !accepted(b)) continue;
        ++report.checked_edges;
        detail::check_interior_edge(k, inc, e, report);
    }
    return report;
}

}  // namespace dualhex

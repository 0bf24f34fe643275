#pragma once
// Open faces: holes where placed elements do not match. `validate` takes every face with
// one cell for boundary, so a hole's vertices and edges would escape the interior checks;
// these are counted and their vertices and edges checked here. Used by
// verify_installation and by the checkers' windows.
#include <cstddef>
#include <span>
#include <sstream>
#include <vector>

#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/incidence.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex::detail {

/// Boundary faces (one cell) that do not lie on the domain's boundary are holes:
/// `validate` treats them as boundary, so their vertices/edges escape the interior checks.
/// Checks those vertices (6 edges) and edges (4 cells) that `accept` admits, adding
/// VertexValence / EdgeCellCount violations to `report`. Returns the number of open faces.
template <class Accept, class OnBoundary>
std::size_t check_open_faces(const CellComplex& cx, const Incidence& inc, Accept&& accept,
                             OnBoundary&& on_domain_boundary, ValidationReport& report) {
    std::size_t open = 0;
    std::vector<char> hole_vertex(cx.n_vertices(), 0), hole_edge(cx.n_edges(), 0);
    for (std::size_t f = 0; f < cx.n_faces(); ++f) {
        const FaceHandle fh(f);
        if (!inc.is_boundary(fh)) continue;
        const auto loop = cx.face_vertices(fh);
        const bool expected = on_domain_boundary(cx, loop);
        if (expected) continue;
        ++open;
        for (VertexHandle v : loop) hole_vertex[v.index()] = 1;
        for (EdgeHandle e : cx.face_edges(fh)) hole_edge[e.index()] = 1;
    }
    for (std::size_t v = 0; v < cx.n_vertices(); ++v) {
        const VertexHandle vh(v);
        if (!hole_vertex[v] || !accept(cx.position(vh))) continue;
        if (const std::size_t n = inc.vertex_edges(vh).size(); n != 6) {
            std::ostringstream os;
            os << "vertex " << v << " at " << cx.position(vh) << " (on an open face) has " << n << " edges, expected 6";
            report.add({ViolationKind::VertexValence, vh, {}, {}, {}, os.str()});
        }
    }
    for (std::size_t e = 0; e < cx.n_edges(); ++e) {
        const EdgeHandle eh(e);
        const auto& ends = cx.edge_vertices(eh);
        if (!hole_edge[e] || !accept(cx.position(ends[0])) || !accept(cx.position(ends[1]))) continue;
        if (const std::size_t n = inc.edge_cells(eh).size(); n != 4) {
            std::ostringstream os;
            os << "edge " << e << " " << cx.position(ends[0]) << "-" << cx.position(ends[1]) << " (on an open face) has "
               << n << " cells, expected 4";
            report.add({ViolationKind::EdgeCellCount, {}, eh, {}, {}, os.str()});
        }
    }
    return open;
}

}  // namespace dualhex::detail

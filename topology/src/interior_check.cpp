// Checks (3) and (4) for interior vertices and edges.
#include <algorithm>

#include "checks.hpp"
#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/link.hpp"

namespace dualhex::detail {
namespace {

// The cells around e, joined through the faces containing e, must form a single cycle:
// as many faces as cells, every cell on exactly two of them, connected.
bool cells_form_one_cycle(const Incidence& inc, EdgeHandle e) {
    const auto cells = inc.edge_cells(e);
    const auto faces = inc.edge_faces(e);
    if (cells.size() < 2 || faces.size() != cells.size()) return false;
    auto slot = [&](CellHandle c) { return static_cast<std::size_t>(std::find(cells.begin(), cells.end(), c) - cells.begin()); };
    std::vector<std::vector<std::size_t>> nbrs(cells.size());
    for (FaceHandle f : faces) {
        const auto fc = inc.face_cells(f);
        if (fc.size() != 2 || fc[0] == fc[1]) return false;
        nbrs[slot(fc[0])].push_back(slot(fc[1]));
        nbrs[slot(fc[1])].push_back(slot(fc[0]));
    }
    if (std::any_of(nbrs.begin(), nbrs.end(), [](const auto& n) { return n.size() != 2; })) return false;
    // Walk the 2-regular graph from cell 0; one cycle iff it visits every cell.
    std::size_t prev = 0, at = nbrs[0][0], steps = 1;
    while (at != 0 && steps <= cells.size()) {
        const std::size_t next = nbrs[at][0] == prev ? nbrs[at][1] : nbrs[at][0];
        prev = at, at = next, ++steps;
    }
    return at == 0 && steps == cells.size();
}

}  // namespace

void check_interior_vertex(const CellComplex& k, const Incidence& inc, VertexHandle v, ValidationReport& report) {
    const std::size_t valence = inc.vertex_edges(v).size();
    if (valence != 6)
        report.add({ViolationKind::VertexValence, v, {}, {}, {}, "interior vertex has " + std::to_string(valence) + " edges"});
    const VertexLink link = vertex_link(k, inc, v);
    if (!link.is_octahedron())
        report.add({ViolationKind::VertexLinkNotOctahedron, v, {}, {}, {},
                    "link has " + std::to_string(link.vertices.size()) + " vertices, " + std::to_string(link.edges.size()) +
                        " edges, " + std::to_string(link.faces.size()) + " faces" +
                        (link.is_closed_connected_surface() ? "" : ", not a closed connected surface")});
    if (auto defect = dual_cube_defect(k, inc, v)) report.add({ViolationKind::DualCellNotCube, v, {}, {}, {}, *defect});
}

void check_interior_edge(const CellComplex&, const Incidence& inc, EdgeHandle e, ValidationReport& report) {
    const std::size_t n = inc.edge_cells(e).size();
    if (n != 4)
        report.add({ViolationKind::EdgeCellCount, {}, e, {}, {}, "interior edge has " + std::to_string(n) + " cells"});
    if (!cells_form_one_cycle(inc, e))
        report.add({ViolationKind::EdgeCellsNotCycle, {}, e, {}, {}, "cells around the edge are not one cycle"});
}

}  // namespace dualhex::detail

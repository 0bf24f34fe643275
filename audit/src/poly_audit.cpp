// Polyhedral mode of the audit (audit.hpp): the file's cells as a CellComplex, judged by
// topology's validate() (DESIGN.md section 4), each violation mapped back to file ids.
#include <array>
#include <map>

#include "audit_modes.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex::audit::detail {
namespace {

using VK = dualhex::ViolationKind;

struct CheckSpec {
    const char* name;
    const char* description;
    std::vector<VK> kinds;
};
const std::vector<CheckSpec>& check_specs() {
    static const std::vector<CheckSpec> specs{
        {"faces-simple", "every face a simple loop of >= 3 distinct points", {VK::FaceTooFewVertices, VK::FaceRepeatedVertex}},
        {"cells-closed", "each cell's faces a closed, connected, consistently oriented sphere",
         {VK::CellRepeatedFace, VK::CellOpenEdge, VK::CellNonManifoldEdge, VK::CellInconsistentOrientation,
          VK::CellNonManifoldVertex, VK::CellDisconnected, VK::CellNotSphere}},
        {"conforming-faces", "every face in <= 2 cells, in 2 with opposite orientations; no duplicate cells",
         {VK::FaceUnused, VK::FaceOvershared, VK::FaceSameOrientation, VK::DuplicateCell}},
        {"vertex-valence", "every interior vertex with 6 edges and an octahedral link",
         {VK::VertexValence, VK::VertexLinkNotOctahedron}},
        {"edge-valence", "every interior edge in 4 cells forming one cycle", {VK::EdgeCellCount, VK::EdgeCellsNotCycle}},
        {"dual-all-hex", "the dual cell of every interior vertex a combinatorial cube", {VK::DualCellNotCube}},
    };
    return specs;
}

Violation locate(const MeshFile& mesh, const MeshComplex& m, const dualhex::Violation& v) {
    const CellComplex& k = m.complex;
    std::vector<std::int64_t> points;
    const auto file_point = [&](VertexHandle u) { return m.file_point[u.index()]; };
    if (v.vertex.valid()) points.push_back(file_point(v.vertex));
    else if (v.edge.valid())
        for (VertexHandle u : k.edge_vertices(v.edge)) points.push_back(file_point(u));
    else if (v.face.valid())
        for (VertexHandle u : k.face_vertices(v.face)) points.push_back(file_point(u));
    const std::int64_t cell = v.cell.valid() ? static_cast<std::int64_t>(mesh.cells[v.cell.index()].index) : -1;
    return at_points(mesh, std::string(to_string(v.kind)) + (v.message.empty() ? "" : ": " + v.message), points, cell);
}

std::map<std::string, std::size_t> keyed(const std::map<int, std::size_t>& h) {
    std::map<std::string, std::size_t> out;
    for (const auto& [k, n] : h) out[std::to_string(k)] = n;
    return out;
}

void statistics(const MeshFile& mesh, const MeshComplex& m, const ValidationReport& report, AuditReport& r) {
    const CellComplex& k = m.complex;
    const Incidence inc(k);
    std::size_t boundary_vertices = 0;
    for (std::size_t v = 0; v < k.n_vertices(); ++v) boundary_vertices += inc.is_boundary(VertexHandle(v)) ? 1 : 0;
    std::map<std::string, std::size_t> types;
    for (const MeshCell& c : mesh.cells) ++types[cell_type_name(c.type)];
    std::size_t hexes = 0;  // cells with 6 quadrilateral faces
    for (std::size_t c = 0; c < k.n_cells(); ++c) {
        const auto hfs = k.cell_halffaces(CellHandle(c));
        bool hex = hfs.size() == 6;
        for (HalfFaceHandle h : hfs) hex = hex && k.face_vertices(h.face()).size() == 4;
        hexes += hex ? 1 : 0;
    }
    r.statistics["cell_types"] = types;
    r.statistics["vertices_used"] = k.n_vertices();
    r.statistics["edges"] = k.n_edges();
    r.statistics["faces"] = k.n_faces();
    r.statistics["cells_not_hexahedra"] = k.n_cells() - hexes;
    r.statistics["face_sizes"] = keyed(face_size_histogram(k));
    r.statistics["euler_characteristic"] = euler_characteristic(k);
    r.statistics["interior_vertices"] = k.n_vertices() - boundary_vertices;
    r.statistics["boundary_vertices"] = boundary_vertices;
    r.statistics["interior_dual_edge_valences"] = keyed(interior_dual_edge_valence_histogram(k, inc));
    r.statistics["checked"] = {{"faces", report.checked_faces}, {"cells", report.checked_cells},
                               {"interior_vertices", report.checked_vertices}, {"interior_edges", report.checked_edges}};
    if (mesh.points.size() > k.n_vertices())
        r.notes.push_back(std::to_string(mesh.points.size() - k.n_vertices()) + " points are in no cell (ignored)");
    if (boundary_vertices > 0)
        r.notes.push_back(std::to_string(boundary_vertices) +
                          " boundary vertices (on a face of one cell) get no valence or dual check");
}

}  // namespace

void audit_polyhedral(const MeshFile& mesh, const AuditOptions& options, AuditReport& r) {
    r.mode = "polyhedral";
    report_progress(options.progress, "complex", 0, 3);
    const MeshComplex m = build_complex(mesh);
    report_progress(options.progress, "validate", 1, 3);
    const ValidationReport report = validate(m.complex);
    std::map<VK, std::size_t> check_of;
    const std::pair<std::size_t, const char*> checked[] = {
        {report.checked_faces, "faces"},          {report.checked_cells, "cells"},
        {report.checked_faces, "faces"},          {report.checked_vertices, "interior vertices"},
        {report.checked_edges, "interior edges"}, {report.checked_vertices, "interior vertices"}};
    for (const CheckSpec& s : check_specs()) {
        for (VK kind : s.kinds) check_of[kind] = r.checks.size();
        const auto& [n, what] = checked[r.checks.size()];
        CheckResult c;
        c.name = s.name;
        c.description = s.description;
        c.checked = n;
        c.checked_what = what;
        r.checks.push_back(std::move(c));
    }
    if (mesh.cells.empty())
        add_violation(r.checks[check_of.at(VK::CellNotSphere)], options.max_listed,
                      Violation{"the file has no volume cells", -1, 0, {}, {}});
    for (const dualhex::Violation& v : report.violations) {
        CheckResult& c = r.checks[check_of.at(v.kind)];
        ++c.violations;
        if (c.first.size() < options.max_listed) c.first.push_back(locate(mesh, m, v));
    }
    report_progress(options.progress, "statistics", 2, 3);
    statistics(mesh, m, report, r);
    r.notes.push_back("topology from point ids only (faces welded by their cyclic sequence of ids); coordinates unused");
    r.notes.push_back("face loops taken as written: outward by the right-hand rule");
}

}  // namespace dualhex::audit::detail

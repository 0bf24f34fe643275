// Hex mode of the audit (audit.hpp): cell checks here, the boundary through
// geometry/hex_topology (exact, on ids), components, scaled Jacobians and edge valences.
#include <algorithm>
#include <map>
#include <numeric>

#include "audit_modes.hpp"
#include "dualhex/grid/input_error.hpp"
#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/geometry/quality.hpp"

namespace dualhex::audit::detail {
namespace {

using geometry::HexMesh;

CheckResult named(std::string name, std::string description) {
    CheckResult c;
    c.name = std::move(name);
    c.description = std::move(description);
    return c;
}

// The hexes with 8 distinct ids, as a HexMesh over all file points; `file_cell[h]` is the
// file index of hex h.
struct Hexes {
    HexMesh mesh;
    std::vector<std::int64_t> file_cell;
};

Hexes check_cells(const MeshFile& mesh, std::size_t max, AuditReport& r) {
    CheckResult is_hex = named("hexahedra", "every volume cell a VTK_HEXAHEDRON");
    CheckResult distinct = named("distinct-vertices", "every hexahedron with 8 distinct point ids");
    if (mesh.cells.empty()) add_violation(is_hex, max, Violation{"the file has no volume cells", -1, 0, {}, {}});
    if (mesh.points.size() > static_cast<std::size_t>(INT32_MAX))  // HexMesh ids are int
        throw InputError(mesh.path, 0, std::to_string(mesh.points.size()) + " points: more than the hex checks' 2^31 - 1");
    Hexes h;
    for (const auto& p : mesh.points) h.mesh.points.emplace_back(p[0], p[1], p[2]);
    for (const MeshCell& c : mesh.cells) {
        const auto cell = static_cast<std::int64_t>(c.index);
        if (c.type != kVtkHexahedron) {
            add_violation(is_hex, max, at_points(mesh, "not a hexahedron (" + cell_type_name(c.type) + ")", c.points, cell));
            continue;
        }
        std::vector<std::int64_t> sorted = c.points;
        std::sort(sorted.begin(), sorted.end());
        const auto rep = std::adjacent_find(sorted.begin(), sorted.end());
        if (rep != sorted.end()) {
            add_violation(distinct, max, at_points(mesh, "hexahedron with point " + std::to_string(*rep) + " repeated", c.points, cell));
            continue;
        }
        std::array<int, 8> q{};
        for (int i = 0; i < 8; ++i) q[static_cast<std::size_t>(i)] = static_cast<int>(c.points[static_cast<std::size_t>(i)]);
        h.mesh.hexes.push_back(q);
        h.file_cell.push_back(cell);
    }
    is_hex.checked = mesh.cells.size();
    is_hex.checked_what = "volume cells";
    distinct.checked = static_cast<std::size_t>(std::count_if(mesh.cells.begin(), mesh.cells.end(),
                                                              [](const MeshCell& c) { return c.type == kVtkHexahedron; }));
    distinct.checked_what = "hexahedra";
    r.checks.push_back(std::move(is_hex));
    r.checks.push_back(std::move(distinct));
    if (h.mesh.hexes.size() != mesh.cells.size())
        r.notes.push_back("the topology checks below ran on the " + std::to_string(h.mesh.hexes.size()) +
                          " valid hexahedra only");
    return h;
}

void check_boundary(const MeshFile& mesh, const Hexes& h, std::size_t max, AuditReport& r) {
    const geometry::BoundaryDefects b = geometry::boundary_defects(h.mesh.hexes, h.mesh.points.size());
    CheckResult faces = named("conforming-faces", "every quad in <= 2 hexes, in 2 with opposite directions");
    for (const auto& f : b.face_defects)
        add_violation(faces, max, at_points(mesh, f.hexes >= 3 ? "quad in " + std::to_string(f.hexes) + " hexes"
                                                                : "quad in 2 hexes with the same direction",
                                            {f.corners.begin(), f.corners.end()}));
    CheckResult edges = named("boundary-edges", "every boundary edge in exactly 2 boundary quads");
    for (const auto& e : b.non_manifold_edges)
        add_violation(edges, max, at_points(mesh, "boundary edge in " + std::to_string(e.quads) + " boundary quads", {e.a, e.b}));
    CheckResult orient = named("boundary-orientation", "the 2 boundary quads at an edge traverse it oppositely");
    for (const auto& e : b.misoriented_edges)
        add_violation(orient, max, at_points(mesh, "boundary quads traverse the edge the same way", {e[0], e[1]}));
    CheckResult verts = named("boundary-vertices", "the boundary quads around a boundary vertex form one cycle");
    for (int v : b.non_manifold_vertices)
        add_violation(verts, max, at_points(mesh, "boundary vertex whose boundary quads are not one cycle", {v}));
    faces.checked = 6 * h.mesh.hexes.size();
    faces.checked_what = "hex faces";
    edges.checked = orient.checked = b.boundary_edges;
    edges.checked_what = orient.checked_what = "boundary edges";
    verts.checked = b.boundary_vertices;
    verts.checked_what = "boundary vertices";
    for (CheckResult* c : {&faces, &edges, &orient, &verts}) r.checks.push_back(std::move(*c));
    r.statistics["boundary_quads"] = b.quads.size();
    r.statistics["boundary_edges"] = b.boundary_edges;
    r.statistics["boundary_vertices"] = b.boundary_vertices;
}

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
}

// Face-connected components of the hexes (quads keyed by their sorted ids).
void check_components(const MeshFile& mesh, const Hexes& h, std::size_t max, AuditReport& r) {
    std::vector<std::pair<std::array<int, 4>, std::size_t>> quads;
    for (std::size_t i = 0; i < h.mesh.hexes.size(); ++i)
        for (const auto& f : geometry::kHexFaces) {
            std::array<int, 4> key{};
            for (int k = 0; k < 4; ++k) key[static_cast<std::size_t>(k)] = h.mesh.hexes[i][static_cast<std::size_t>(f[static_cast<std::size_t>(k)])];
            std::sort(key.begin(), key.end());
            quads.emplace_back(key, i);
        }
    std::sort(quads.begin(), quads.end());
    std::vector<std::size_t> parent(h.mesh.hexes.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (std::size_t i = 1; i < quads.size(); ++i)
        if (quads[i].first == quads[i - 1].first)
            parent[find_root(parent, quads[i].second)] = find_root(parent, quads[i - 1].second);
    std::map<std::size_t, std::pair<std::size_t, std::size_t>> size_and_first;  // root -> (hexes, first hex)
    for (std::size_t i = 0; i < parent.size(); ++i) {
        auto [it, fresh] = size_and_first.try_emplace(find_root(parent, i), 0, i);
        ++it->second.first;
    }
    CheckResult one = named("connected", "one face-connected component of hexes");
    std::vector<std::size_t> sizes;
    for (const auto& [root, sf] : size_and_first) sizes.push_back(sf.first);
    std::sort(sizes.rbegin(), sizes.rend());
    if (size_and_first.size() > 1)
        for (const auto& [root, sf] : size_and_first) {
            const std::size_t first = sf.second;
            add_violation(one, max, at_points(mesh, "component of " + std::to_string(sf.first) + " hexes, its first hex",
                                              {h.mesh.hexes[first].begin(), h.mesh.hexes[first].end()}, h.file_cell[first]));
        }
    one.checked = h.mesh.hexes.size();
    one.checked_what = "hexes";
    r.checks.push_back(std::move(one));
    r.statistics["hex_components"] = sizes;
}

void check_jacobians(const MeshFile& mesh, const Hexes& h, std::size_t max, AuditReport& r) {
    const std::vector<double> sj = geometry::scaled_jacobians(h.mesh);
    CheckResult inverted = named("not-inverted", "scaled Jacobian > 0 for every hex");
    static const double kEdges[] = {-1.0, 0.0, 0.2, 0.4, 0.6, 0.8, 1.0};
    static const char* kBins[] = {"[-1,0]", "(0,0.2)", "[0.2,0.4)", "[0.4,0.6)", "[0.6,0.8)", "[0.8,1]"};
    std::map<std::string, std::size_t> histogram;
    double min = sj.empty() ? 0 : sj[0], sum = 0;
    for (std::size_t i = 0; i < sj.size(); ++i) {
        min = std::min(min, sj[i]);
        sum += sj[i];
        if (sj[i] <= 0) {
            add_violation(inverted, max, at_points(mesh, "scaled Jacobian " + std::to_string(sj[i]),
                                                   {h.mesh.hexes[i].begin(), h.mesh.hexes[i].end()}, h.file_cell[i]));
            ++histogram[kBins[0]];
            continue;
        }
        int bin = 1;
        while (bin < 5 && sj[i] >= kEdges[bin + 1]) ++bin;
        ++histogram[kBins[bin]];
    }
    inverted.checked = sj.size();
    inverted.checked_what = "hexes";
    r.checks.push_back(std::move(inverted));
    r.statistics["scaled_jacobian_histogram"] = histogram;
    r.statistics["scaled_jacobian_min"] = min;
    r.statistics["scaled_jacobian_mean"] = sj.empty() ? 0.0 : sum / static_cast<double>(sj.size());
}

// Hexes per edge, split by whether the edge lies on a boundary quad.
void edge_valences(const Hexes& h, AuditReport& r) {
    auto key = [](int a, int b) {
        return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
    };
    std::vector<std::uint64_t> edges, boundary;
    for (const auto& hex : h.mesh.hexes)
        for (const auto& e : geometry::kHexEdgeCorners) edges.push_back(key(hex[static_cast<std::size_t>(e[0])], hex[static_cast<std::size_t>(e[1])]));
    for (const auto& q : geometry::boundary_quads(h.mesh))
        for (int k = 0; k < 4; ++k) boundary.push_back(key(q[static_cast<std::size_t>(k)], q[static_cast<std::size_t>((k + 1) % 4)]));
    std::sort(edges.begin(), edges.end());
    std::sort(boundary.begin(), boundary.end());
    std::map<std::string, std::size_t> interior_hist, boundary_hist;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        const bool on_boundary = std::binary_search(boundary.begin(), boundary.end(), edges[i]);
        ++(on_boundary ? boundary_hist : interior_hist)[std::to_string(j - i)];
        i = j;
    }
    r.statistics["interior_edge_valences"] = interior_hist;
    r.statistics["boundary_edge_valences"] = boundary_hist;
}

void boundary_components(const Hexes& h, AuditReport& r) {
    const geometry::HexTopology t = geometry::check_hex_topology(h.mesh, 0);
    nlohmann::json list = nlohmann::json::array();
    for (const auto& c : t.boundary_components)
        list.push_back({{"V", c.vertices}, {"E", c.edges}, {"F", c.faces}, {"euler", c.euler()}});
    r.statistics["boundary_components"] = list;
}

}  // namespace

void audit_hex(const MeshFile& mesh, const AuditOptions& options, AuditReport& r) {
    r.mode = "hex";
    const auto step = [&](const char* name, std::size_t done) { report_progress(options.progress, name, done, 6); };
    step("cells", 0);
    const Hexes h = check_cells(mesh, options.max_listed, r);
    r.statistics["hexes"] = h.mesh.hexes.size();
    step("boundary", 1);
    check_boundary(mesh, h, options.max_listed, r);
    step("components", 2);
    check_components(mesh, h, options.max_listed, r);
    step("scaled Jacobians", 3);
    check_jacobians(mesh, h, options.max_listed, r);
    step("edge valences", 4);
    edge_valences(h, r);
    step("boundary components", 5);
    boundary_components(h, r);
    r.notes.push_back("topology from point ids only; the scaled Jacobian is the one floating-point check");
}

}  // namespace dualhex::audit::detail

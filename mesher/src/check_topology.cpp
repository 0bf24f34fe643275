// The check stage (check_topology.hpp).
#include "dualhex/mesher/check_topology.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include <Eigen/Geometry>

#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/geometry/quality.hpp"

namespace dualhex::mesher {
namespace {

void list(std::vector<std::string>& problems, const char* what, std::size_t count,
          const std::vector<geometry::DefectLocation>& first) {
    if (count == 0) return;
    std::string s = std::to_string(count) + " " + what;
    for (std::size_t i = 0; i < first.size(); ++i) s += (i == 0 ? ", e.g. " : "; ") + first[i].describe();
    problems.push_back(s);
}

int root_of(std::vector<int>& parent, int x) {
    while (parent[static_cast<std::size_t>(x)] != x) x = parent[static_cast<std::size_t>(x)] =
                                                       parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    return x;
}

// Where each boundary component is: its quads and bounding box (classes of boundary quads
// under "share a vertex", as hex_topology counts them), largest first.
std::string locate_boundary_components(const geometry::HexMesh& mesh) {
    const auto quads = geometry::boundary_quads(mesh);
    std::vector<int> parent(mesh.points.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& q : quads)
        for (int i = 1; i < 4; ++i) {
            const int a = root_of(parent, q[0]), b = root_of(parent, q[static_cast<std::size_t>(i)]);
            if (a != b) parent[static_cast<std::size_t>(a)] = b;
        }
    struct Piece {
        std::size_t quads = 0;
        Eigen::AlignedBox3d box;
    };
    std::vector<Piece> pieces(mesh.points.size());
    for (const auto& q : quads) {
        Piece& p = pieces[static_cast<std::size_t>(root_of(parent, q[0]))];
        ++p.quads;
        for (int v : q) p.box.extend(mesh.points[static_cast<std::size_t>(v)]);
    }
    std::erase_if(pieces, [](const Piece& p) { return p.quads == 0; });
    std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.quads > b.quads; });
    std::string out;
    char buf[200];
    for (std::size_t i = 0; i < pieces.size() && i < 8; ++i) {
        const auto& b = pieces[i].box;
        std::snprintf(buf, sizeof buf, "%scomponent %zu: %zu quads in (%.4g %.4g %.4g)-(%.4g %.4g %.4g)", i ? "; " : "",
                      i + 1, pieces[i].quads, b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(),
                      b.max().z());
        out += buf;
    }
    return out;
}

}  // namespace

TopologyCheck check_topology(const geometry::HexMesh& mesh, const geometry::TriangleSurface& input) {
    const geometry::HexTopology t = geometry::check_hex_topology(mesh);
    TopologyCheck out;
    out.non_manifold_edges = t.non_manifold_edges;
    out.non_manifold_vertices = t.non_manifold_vertices;
    out.misoriented_edges = t.misoriented_edges;
    out.face_defects = t.face_defects + t.degenerate_hexes;
    out.manifold = out.non_manifold_edges == 0 && out.non_manifold_vertices == 0 && out.misoriented_edges == 0 &&
                   out.face_defects == 0;
    out.hex_components = t.hex_components;
    const geometry::TopologyComparison cmp =
        geometry::compare_topology(t.boundary_components, geometry::surface_topology(input));
    out.euler = cmp.mesh_euler;
    out.input_euler = cmp.surface_euler;
    out.matches = out.manifold && cmp.same;
    list(out.problems, "non-manifold boundary edges", t.non_manifold_edges, t.first_non_manifold_edges);
    list(out.problems, "non-manifold boundary vertices", t.non_manifold_vertices, t.first_non_manifold_vertices);
    list(out.problems, "misoriented boundary edges", t.misoriented_edges, t.first_misoriented_edges);
    list(out.problems, "face defects (a face in >= 3 hexes or twice the same way)", t.face_defects,
         t.first_face_defects);
    if (t.degenerate_hexes > 0) out.problems.push_back(std::to_string(t.degenerate_hexes) + " degenerate hexes");
    if (!cmp.same)
        out.problems.push_back("boundary topology differs from the input's: " + cmp.describe() + "; boundary " +
                               locate_boundary_components(mesh));
    return out;
}

}  // namespace dualhex::mesher

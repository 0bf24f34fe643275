// The check stage (check_topology.hpp).
#include "dualhex/mesher/check_topology.hpp"

#include "dualhex/geometry/hex_topology.hpp"

namespace dualhex::mesher {
namespace {

void list(std::vector<std::string>& problems, const char* what, std::size_t count,
          const std::vector<geometry::DefectLocation>& first) {
    if (count == 0) return;
    std::string s = std::to_string(count) + " " + what;
    for (std::size_t i = 0; i < first.size(); ++i) s += (i == 0 ? ", e.g. " : "; ") + first[i].describe();
    problems.push_back(s);
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
    if (!cmp.same) out.problems.push_back("boundary topology differs from the input's: " + cmp.describe());
    return out;
}

}  // namespace dualhex::mesher

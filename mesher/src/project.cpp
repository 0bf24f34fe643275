// The project stage (project.hpp).
#include "dualhex/mesher/project.hpp"

#include "dualhex/geometry/quality.hpp"

namespace dualhex::mesher {

BoundaryProjection project_boundary(geometry::HexMesh& mesh, const geometry::AabbTree& tree) {
    BoundaryProjection out;
    out.on_boundary.assign(mesh.points.size(), 0);
    for (const auto& q : geometry::boundary_quads(mesh))
        for (int v : q) out.on_boundary[static_cast<std::size_t>(v)] = 1;
    out.unprojected = mesh.points;
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
        if (out.on_boundary[v]) {
            mesh.points[v] = tree.closest_point(mesh.points[v]).point;
            ++out.boundary_vertices;
        }
    return out;
}

}  // namespace dualhex::mesher

#include <array>

#include "audit_modes.hpp"
#include "dualhex/topology/complex_builder.hpp"

namespace dualhex::audit::detail {
namespace {

using Loops = std::vector<std::vector<int>>;
// Outward faces in VTK corner order (right-hand normal out for a positively oriented cell).
const Loops kTetraFaces{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
const Loops kHexFaces{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
const Loops kWedgeFaces{{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
const Loops kPyramidFaces{{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};

}  // namespace

std::vector<std::vector<std::int64_t>> cell_faces(const MeshCell& cell) {
    if (cell.type == kVtkPolyhedron) return cell.faces;
    const Loops* table = cell.type == kVtkTetra         ? &kTetraFaces
                         : cell.type == kVtkHexahedron ? &kHexFaces
                         : cell.type == kVtkWedge      ? &kWedgeFaces
                         : cell.type == kVtkPyramid    ? &kPyramidFaces
                                                       : nullptr;
    std::vector<std::vector<std::int64_t>> faces;
    if (table == nullptr) return faces;
    for (const auto& loop : *table) {
        std::vector<std::int64_t> f;
        for (int corner : loop) f.push_back(cell.points[static_cast<std::size_t>(corner)]);
        faces.push_back(std::move(f));
    }
    return faces;
}

MeshComplex build_complex(const MeshFile& mesh, const std::vector<LatticePoint>& positions) {
    MeshComplex out;
    std::vector<std::int64_t> vertex_of(mesh.points.size(), -1);
    ComplexBuilder b;
    std::vector<VertexHandle> loop;
    std::vector<HalfFaceHandle> halffaces;
    for (const MeshCell& cell : mesh.cells) {
        halffaces.clear();
        for (const auto& face : cell_faces(cell)) {
            loop.clear();
            for (std::int64_t p : face) {
                auto& v = vertex_of[static_cast<std::size_t>(p)];
                if (v < 0) {  // the first use of the point: a new vertex (welded by id, never by position)
                    v = static_cast<std::int64_t>(out.file_point.size());
                    out.file_point.push_back(p);
                    b.add_vertex_unwelded(positions.empty() ? LatticePoint{v, 0, 0} : positions[static_cast<std::size_t>(p)]);
                }
                loop.push_back(VertexHandle(static_cast<std::size_t>(v)));
            }
            halffaces.push_back(b.add_face(loop));
        }
        b.add_cell(halffaces);
    }
    out.complex = std::move(b).build();
    return out;
}

}  // namespace dualhex::audit::detail

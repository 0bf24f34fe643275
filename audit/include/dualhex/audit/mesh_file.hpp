#pragma once
// A volume mesh as read from someone's file, before any check: points, and cells as VTK
// cell types with point ids (polyhedra with their face streams), each cell remembering
// the line of the file it came from so that every violation can be located.
//
// Readers (read_mesh.hpp) are strict: every malformed line is an InputError naming the
// file, the line and the offending value; ids are checked against the point count, so a
// MeshFile is always internally consistent (every id in [0, points.size())).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dualhex::audit {

/// VTK cell type numbers (vtkCellType.h) the audit understands.
enum VtkCellType : int {
    kVtkVertex = 1, kVtkLine = 3, kVtkTriangle = 5, kVtkPolygon = 7, kVtkQuad = 9,
    kVtkTetra = 10, kVtkHexahedron = 12, kVtkWedge = 13, kVtkPyramid = 14, kVtkPolyhedron = 42
};
/// "hexahedron", "polyhedron", ... ; "type N" for others.
[[nodiscard]] std::string cell_type_name(int type);
/// Is `type` a 3D cell type (tet, hex, wedge, pyramid, polyhedron)?
[[nodiscard]] bool is_volume_type(int type);
/// The number of points of a fixed-size cell type (0 for polygon / polyhedron / unknown).
[[nodiscard]] int fixed_point_count(int type);

struct MeshCell {
    int type = 0;
    std::vector<std::int64_t> points;                   ///< as listed (polyhedron: as in the file, may be empty)
    std::vector<std::vector<std::int64_t>> faces;       ///< polyhedron only: the face stream's loops
    int line = 0;                                       ///< 1-based line of the file (0: unknown)
    std::size_t index = 0;                              ///< the cell's index among all cells of the file
};

struct MeshFile {
    std::string path;
    std::string format;  ///< "vtk", "vtu", "medit"
    std::vector<std::array<double, 3>> points;
    std::vector<MeshCell> cells;
    /// Lower-dimensional cells (VTK: types < 10; MEDIT: Triangles, Quadrilaterals, Edges...)
    /// carried by the file but not part of the volume mesh; counted, not audited.
    std::size_t lower_dimensional_cells = 0;
};

}  // namespace dualhex::audit

#pragma once
// Writing an all-hex mesh: VTK legacy (.vtk, ASCII, VTK_HEXAHEDRON = 12), VTK XML
// unstructured grid (.vtu, ASCII) and MEDIT (.mesh, "Hexahedra", 1-based).
//
// Input : HexMesh — points, and hexes as 8 point ids in VTK_HEXAHEDRON order (0-3 the
//         bottom quad, counter-clockwise seen from the top; 4-7 above 0-3). MEDIT uses the
//         same corner order. A path and `overwrite`. Optional HexCellData: per-hex
//         values written as cell data, so ParaView can colour by them — VTK legacy
//         CELL_DATA (SCALARS scaled_jacobian double, SCALARS level int), VTU <CellData>
//         (Float64 scaled_jacobian, Int32 level); MEDIT has no named fields and takes the
//         level as each hexahedron's reference (0 without levels). An empty field is not
//         written.
// Output: the file. Throws std::runtime_error (message names the path) if it exists and
//         overwrite is false (checked before anything is written), if it cannot be
//         written, if a hex refers to a point out of range or a non-empty cell field
//         does not have one value per hex. Numbers are written with
//         17 significant digits (doubles round-trip).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace dualhex::geometry {

struct HexMesh {
    std::vector<Eigen::Vector3d> points;
    std::vector<std::array<int, 8>> hexes;
};

/// Per-hex values, indexed like HexMesh::hexes; each field empty or one value per hex.
struct HexCellData {
    std::vector<double> scaled_jacobian;
    std::vector<int> level;  ///< octree level of the hex (mesher/cell_levels.hpp)
};

void write_vtk_legacy(const std::string& path, const HexMesh& mesh, bool overwrite = false,
                      const HexCellData& cells = {});
void write_vtu(const std::string& path, const HexMesh& mesh, bool overwrite = false, const HexCellData& cells = {});
void write_medit(const std::string& path, const HexMesh& mesh, bool overwrite = false,
                 const HexCellData& cells = {});
/// By extension: .vtk, .vtu or .mesh (else std::invalid_argument).
void write_hex_mesh(const std::string& path, const HexMesh& mesh, bool overwrite = false,
                    const HexCellData& cells = {});

/// Throws std::runtime_error("<path>: exists (pass overwrite to replace it)") if `path`
/// exists and !overwrite. Shared by every writer of this layer.
void check_can_write(const std::string& path, bool overwrite);

}  // namespace dualhex::geometry

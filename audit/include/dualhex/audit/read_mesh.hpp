#pragma once
// Strict readers of volume meshes into a MeshFile (mesh_file.hpp).
//
//   .vtk   VTK legacy, DATASET UNSTRUCTURED_GRID, ASCII or BINARY (big-endian): CELLS n
//          size with one "count ids..." row per cell, a VTK_POLYHEDRON row being its face
//          stream "size nfaces n0 ids... n1 ids...", then CELL_TYPES; or the version-5
//          layout (OFFSETS / CONNECTIVITY, no polyhedra). POINT_DATA / CELL_DATA / FIELD
//          after the cells are ignored.
//   .vtu   VTK XML UnstructuredGrid, one Piece; DataArrays format="ascii", "binary"
//          (inline base64) or "appended" (<AppendedData> raw or base64); header_type UInt32
//          or UInt64, no compressor; polyhedra through the "faces" / "faceoffsets" arrays.
//   .mesh  MEDIT (ASCII, MeshVersionFormatted 1 or 2, Dimension 3): Vertices, Tetrahedra,
//          Prisms, Pyramids, Hexahedra (1-based ids, a reference per entry); Edges,
//          Triangles, Quadrilaterals, Corners, Ridges, Required* are counted as
//          lower-dimensional and skipped.
//
// Errors throw dualhex::InputError(file, line, message) naming the offending token: a file
// that is missing, not a regular file (a FIFO would hang), truncated, a count that the
// file's size cannot hold (checked before allocating), a number that does not parse or is
// not finite, an id out of range, an unknown cell type or keyword, inconsistent face streams
// or offsets. Reading never asserts and never allocates more than a constant times the file.
#include <string>

#include "dualhex/audit/mesh_file.hpp"

namespace dualhex::audit {

[[nodiscard]] MeshFile read_vtk_legacy(const std::string& path);
[[nodiscard]] MeshFile read_vtu(const std::string& path);
[[nodiscard]] MeshFile read_medit(const std::string& path);
/// By extension (.vtk, .vtu, .mesh); any other extension is an InputError.
[[nodiscard]] MeshFile read_mesh(const std::string& path);

}  // namespace dualhex::audit

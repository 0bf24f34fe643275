#pragma once
// The topological dual of the interior: one dual cell per interior vertex v, whose
//   dual vertices = cells incident to v,
//   dual edges    = faces incident to v (joining their two cells),
//   dual faces    = edges incident to v (the cycle of cells around the edge).
// A combinatorial cube has 8 dual vertices, 12 dual edges, 6 quadrilateral dual faces,
// every dual vertex of degree 3, every dual edge in exactly 2 dual faces, connected.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "dualhex/topology/incidence.hpp"

namespace dualhex {

/// std::nullopt if the dual cell of v is a combinatorial cube, else the first reason
/// it is not (checked on the dual structure itself, not inferred from valences).
[[nodiscard]] std::optional<std::string> dual_cube_defect(const CellComplex& complex, const Incidence& incidence,
                                                          VertexHandle v);

/// Hexes over dual vertices (= primal cells). Each hex is in VTK_HEXAHEDRON order: 0-3 a
/// quad whose right-hand normal points into the hex, 4-7 the opposite quad with
/// hex[i + 4] adjacent to hex[i]. The order is derived from the primal orientation, so
/// with dual vertices placed inside their cells the hexes have positive volume.
struct HexMesh {
    std::vector<std::array<CellHandle, 8>> hexes;
    std::vector<VertexHandle> primal_vertex;  // the interior vertex each hex is dual to
};

struct DualError {
    VertexHandle vertex;
    std::string message;
};

struct DualResult {
    HexMesh mesh;
    std::vector<DualError> errors;  // interior vertices whose dual cell is not a cube
};

/// The ordered hex of v's dual cell, or std::nullopt if it is not a cube.
[[nodiscard]] std::optional<std::array<CellHandle, 8>> dual_hex(const CellComplex& complex,
                                                                 const Incidence& incidence, VertexHandle v);

/// The dual of every interior vertex.
[[nodiscard]] DualResult interior_dual(const CellComplex& complex, const Incidence& incidence);
[[nodiscard]] DualResult interior_dual(const CellComplex& complex);

struct DualCounts {
    std::size_t interior_vertices = 0;
    std::size_t hexes = 0;      // interior vertices whose dual cell is a cube
    std::size_t non_cubes = 0;  // the others
};
[[nodiscard]] DualCounts count_dual(const CellComplex& complex);

}  // namespace dualhex

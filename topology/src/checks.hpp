#pragma once
// The individual checks behind validate(), one family per file.
#include "dualhex/topology/incidence.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex::detail {

/// (1) for one face.
void check_face(const CellComplex& k, FaceHandle f, ValidationReport& report);
/// (1) for one cell: its half-faces bound an oriented, connected genus-0 surface.
void check_cell(const CellComplex& k, CellHandle c, ValidationReport& report);
/// (2) for one face.
void check_face_conformity(const Incidence& inc, FaceHandle f, ValidationReport& report);
/// (2) duplicate cells, over all cells.
void check_duplicate_cells(const CellComplex& k, ValidationReport& report);
/// (3) for one interior vertex / edge.
void check_interior_vertex(const CellComplex& k, const Incidence& inc, VertexHandle v, ValidationReport& report);
void check_interior_edge(const CellComplex& k, const Incidence& inc, EdgeHandle e, ValidationReport& report);

}  // namespace dualhex::detail

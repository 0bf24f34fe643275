#pragma once
// The singular structure of a complex (DESIGN.md section 4, last paragraph).
#include <cstdint>
#include <map>

#include "dualhex/topology/incidence.hpp"

namespace dualhex {

/// size -> number of faces with that many loop vertices, over all faces (F3, F4, ...).
[[nodiscard]] std::map<int, std::size_t> face_size_histogram(const CellComplex& complex);

/// valence -> count over faces all of whose vertices are interior: such a primal k-gon is
/// a dual edge with k hexes around it.
[[nodiscard]] std::map<int, std::size_t> interior_dual_edge_valence_histogram(const CellComplex& complex,
                                                                              const Incidence& incidence);
[[nodiscard]] std::map<int, std::size_t> interior_dual_edge_valence_histogram(const CellComplex& complex);

/// Number of cells that are not plain hexahedra (6 faces, all quadrilaterals).
[[nodiscard]] std::size_t non_hex_cell_count(const CellComplex& complex);

/// V - E + F - C (1 for a ball).
[[nodiscard]] std::int64_t euler_characteristic(const CellComplex& complex);

}  // namespace dualhex

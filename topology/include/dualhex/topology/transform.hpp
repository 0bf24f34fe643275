#pragma once
// Moving a whole complex by a cube symmetry plus an integer translation.
#include "dualhex/topology/cell_complex.hpp"
#include "dualhex/topology/cube_symmetry.hpp"

namespace dualhex {

/// Every position p becomes symmetry.apply(p) + translation; vertex, edge, face and cell
/// ids are unchanged. A reflection (determinant -1) turns outward loops inward, so every
/// cell half-face is then flipped (side ^ 1) to keep cells outward-oriented.
[[nodiscard]] CellComplex transform(const CellComplex& complex, const CubeSymmetry& symmetry,
                                    const LatticePoint& translation = {});

}  // namespace dualhex

#pragma once
// Grids without hanging nodes as cell complexes: every leaf a hexahedral cell.
//
// Vertex lattice keys are the leaf corners in cells of the common level (corner (a,b,c)
// of leaf (L,i,j,k) is the point (i+a, j+b, k+c)); shared corners and faces weld by
// exact key in ComplexBuilder. Each hex has 6 quads, counter-clockwise seen from outside
// (the CellComplex orientation convention), so neighbours use opposite sides.
#include <span>
#include <vector>

#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/topology/cell_complex.hpp"

namespace dualhex {

/// Leaves all of one level (any set: a box, a whole uniform grid) as a hex complex.
/// Throws InputError naming two leaves of different levels (that would leave hanging
/// nodes); an empty span gives an empty complex. Cell n is leaves[n].
[[nodiscard]] CellComplex leaves_to_complex(std::span<const Leaf> leaves);

/// A whole grid as a hex complex; the grid must be uniform (no hanging nodes), else
/// InputError naming two leaves of different levels with their source lines.
[[nodiscard]] CellComplex box_to_complex(const LeafGrid& grid);

/// The leaves of `level` filling the box [lo, hi) of leaf positions, x fastest.
/// Throws InputError if the box is empty-inverted or leaves the root cube.
[[nodiscard]] std::vector<Leaf> leaf_box(int level, const LatticePoint& lo, const LatticePoint& hi);

}  // namespace dualhex

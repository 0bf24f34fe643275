#pragma once
// Internal to the optimise stage: the optimiser's contract judged place by place after a
// run that moved vertices in several separate places at once (the release's region runs).
//
// Why: optimise_mesh checks its contract once, on all hexes of the run: one place's worse
// minimum is hidden while another place holds the run's minimum (measured on cgal_elephant:
// a hex at -4e-7 went to -3e-5 while one at -3e-4 elsewhere rose to -1.7e-4). Each place
// is judged alone here and a worse one put back.
//
// A place: the moved vertices (position differs from `before`) joined through the hexes
// they share; its hexes are those with a moved corner. Hexes without one are unchanged.
// Compared before (`sj_before`) and after: hexes inverted (<= 0 or NaN), hexes <= `flat`,
// their minimum. Put back (positions of its vertices = `before`, so its hexes' values are
// those of `sj_before` again, bit for bit) if any of the three is worse. Serial, in vertex
// order.
#include <cstddef>
#include <vector>

#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::mesher::detail {

struct PlaceGuardResult {
    std::size_t places = 0;    ///< places with a moved vertex
    std::size_t restored = 0;  ///< of them put back
};

PlaceGuardResult restore_worse_places(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& before,
                                      const std::vector<double>& sj_before, double flat);

}  // namespace dualhex::mesher::detail

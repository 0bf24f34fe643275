#pragma once
// A complex filling the root cube [0, n]^3 moved so that its root corner `corner` (bit a:
// the high side on axis a) is at the origin and the root lies in the positive octant (a
// reflection keeps cells outward, transform.hpp): what check_boundary_vertices expects.
#include <array>

#include "dualhex/topology/transform.hpp"

namespace dualhex::test {

inline CellComplex root_corner_at_origin(const CellComplex& cx, std::int64_t n, int corner) {
    std::array<int, 3> sign{};
    LatticePoint t{0, 0, 0};
    for (int a = 0; a < 3; ++a) {
        const bool high = (corner >> a) & 1;
        sign[static_cast<std::size_t>(a)] = high ? -1 : 1;
        t[a] = high ? n : 0;
    }
    return transform(cx, CubeSymmetry({0, 1, 2}, sign), t);
}

}  // namespace dualhex::test

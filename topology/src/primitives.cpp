#include "dualhex/topology/primitives.hpp"

#include <algorithm>
#include <stdexcept>

#include "dualhex/topology/complex_builder.hpp"

namespace dualhex {

std::vector<std::vector<LatticePoint>> cube_loops(const LatticePoint& c, std::int64_t s) {
    auto p = [&](int x, int y, int z) { return c + LatticePoint{x * s, y * s, z * s}; };
    return {
        {p(0, 0, 0), p(0, 0, 1), p(0, 1, 1), p(0, 1, 0)},  // x = 0, normal -x
        {p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1)},  // x = 1, normal +x
        {p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1)},  // y = 0, normal -y
        {p(0, 1, 0), p(0, 1, 1), p(1, 1, 1), p(1, 1, 0)},  // y = 1, normal +y
        {p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0)},  // z = 0, normal -z
        {p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)},  // z = 1, normal +z
    };
}

CellComplex make_box(const LatticePoint& origin, std::array<int, 3> n, std::int64_t size) {
    if (n[0] <= 0 || n[1] <= 0 || n[2] <= 0 || size <= 0) throw std::invalid_argument("make_box: non-positive extent");
    const auto cells = static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(n[2]);
    ComplexBuilder builder;
    const auto m = [&](int a) { return static_cast<std::size_t>(n[a]); };
    builder.reserve((m(0) + 1) * (m(1) + 1) * (m(2) + 1), 3 * cells + m(0) * m(1) + m(1) * m(2) + m(0) * m(2), cells);
    for (int i = 0; i < n[0]; ++i)
        for (int j = 0; j < n[1]; ++j)
            for (int k = 0; k < n[2]; ++k)
                builder.add_cell_from_loops(cube_loops(origin + LatticePoint{i * size, j * size, k * size}, size));
    return std::move(builder).build();
}

}  // namespace dualhex

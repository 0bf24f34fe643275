#include "dualhex/grid/grid_complex.hpp"

#include <array>

#include "dualhex/grid/input_error.hpp"
#include "dualhex/topology/complex_builder.hpp"

namespace dualhex {

namespace {

// The unit cube's faces as corner-offset loops, counter-clockwise seen from outside
// (right-hand normal pointing out): x-, x+, y-, y+, z-, z+.
constexpr std::array<std::array<std::array<int, 3>, 4>, 6> kHexFaces{{
    {{{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}},
    {{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}},
    {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}},
    {{{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}}},
    {{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}},
    {{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}},
}};

void add_hex(ComplexBuilder& builder, const Leaf& leaf) {
    std::array<HalfFaceHandle, 6> sides;
    for (std::size_t f = 0; f < 6; ++f) {
        std::array<VertexHandle, 4> loop;
        for (std::size_t v = 0; v < 4; ++v) {
            const auto& o = kHexFaces[f][v];
            loop[v] = builder.add_vertex({leaf.i + o[0], leaf.j + o[1], leaf.k + o[2]});
        }
        sides[f] = builder.add_face(loop);
    }
    builder.add_cell(sides);
}

}  // namespace

CellComplex leaves_to_complex(std::span<const Leaf> leaves) {
    for (const Leaf& l : leaves)
        if (l.level != leaves.front().level)
            throw InputError({}, 0, "hanging nodes: leaves " + to_string(leaves.front()) + " and " + to_string(l) +
                                        " have different levels; box_to_complex needs one level");
    ComplexBuilder builder;
    const std::size_t n = leaves.size();
    builder.reserve(n + 3 * n / 2 + 64, 3 * n + 64, n);
    for (const Leaf& l : leaves) add_hex(builder, l);
    return std::move(builder).build();
}

CellComplex box_to_complex(const LeafGrid& grid) {
    for (std::size_t n = 1; n < grid.size(); ++n)
        if (grid.leaf(n).level != grid.leaf(0).level)
            throw InputError(grid.source(), grid.line(n),
                             "hanging nodes: leaves " + grid.describe(0) + " and " + grid.describe(n) +
                                 " have different levels; box_to_complex needs a grid of one level");
    return leaves_to_complex(grid.leaves());
}

std::vector<Leaf> leaf_box(int level, const LatticePoint& lo, const LatticePoint& hi) {
    const Leaf first{level, lo.x, lo.y, lo.z}, last{level, hi.x - 1, hi.y - 1, hi.z - 1};
    if (!first.valid() || !last.valid() || lo.x >= hi.x || lo.y >= hi.y || lo.z >= hi.z)
        throw InputError({}, 0, "leaf box from " + to_string(first) + " to " + to_string(last) +
                                    " is empty or leaves the root cube");
    std::vector<Leaf> out;
    for (std::int64_t k = lo.z; k < hi.z; ++k)
        for (std::int64_t j = lo.y; j < hi.y; ++j)
            for (std::int64_t i = lo.x; i < hi.x; ++i) out.push_back({level, i, j, k});
    return out;
}

}  // namespace dualhex

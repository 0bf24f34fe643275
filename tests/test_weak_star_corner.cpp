// W11's two local checks (checkers/src/weak_star_pair.hpp) on hand-made complexes: a cube
// at v passes as a piece, and two cubes across a quadrant pass as a pair; each wrong
// piece or pair below is refused, with a reason.
#include <gtest/gtest.h>

#include <array>

#include "dualhex/topology/complex_builder.hpp"
#include "weak_star_pair.hpp"

namespace dualhex {
namespace {

using weak_stars::corner_piece_defect;
using weak_stars::corner_quadrant_defect;

struct BoxOptions {
    int split_face = -1;  ///< 2 * axis + (hi side): that face as two triangles (diagonal p0-p2)
    bool inward = false;  ///< every loop reversed
};

// The box [lo, hi] as one cell. Face (axis a, side): corners p0..p3 over the other two axes
// b = a + 1, c = a + 2 (mod 3), whose loop's right-hand normal is +a; reversed on the lo side.
void add_box(ComplexBuilder& builder, const LatticePoint& lo, const LatticePoint& hi, BoxOptions o = {}) {
    std::vector<HalfFaceHandle> faces;
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            std::array<LatticePoint, 4> p{};
            const std::array<std::array<bool, 2>, 4> at{{{false, false}, {true, false}, {true, true}, {false, true}}};
            for (int k = 0; k < 4; ++k) {
                p[static_cast<std::size_t>(k)][a] = side ? hi[a] : lo[a];
                p[static_cast<std::size_t>(k)][b] = at[static_cast<std::size_t>(k)][0] ? hi[b] : lo[b];
                p[static_cast<std::size_t>(k)][c] = at[static_cast<std::size_t>(k)][1] ? hi[c] : lo[c];
            }
            std::vector<std::vector<LatticePoint>> loops;
            if (o.split_face == 2 * a + side) loops = {{p[0], p[1], p[2]}, {p[0], p[2], p[3]}};
            else loops = {{p[0], p[1], p[2], p[3]}};
            for (auto& loop : loops) {
                if ((side == 0) != o.inward) std::reverse(loop.begin(), loop.end());
                std::vector<VertexHandle> vs;
                for (const LatticePoint& q : loop) vs.push_back(builder.add_vertex(q));
                faces.push_back(builder.add_face(vs));
            }
        }
    builder.add_cell(faces);
}

CellComplex boxes(const std::vector<std::pair<LatticePoint, LatticePoint>>& bs, std::vector<BoxOptions> o = {}) {
    ComplexBuilder builder;
    o.resize(bs.size());
    for (std::size_t i = 0; i < bs.size(); ++i) add_box(builder, bs[i].first, bs[i].second, o[i]);
    return std::move(builder).build();
}

constexpr std::array<int, 3> kPlus{1, 1, 1};
const LatticePoint kO{}, kTwo{2, 2, 2};

TEST(CornerPiece, ACubeAtItsCornerPasses) {
    EXPECT_EQ(corner_piece_defect(boxes({{kO, kTwo}}), kPlus), std::nullopt);
    EXPECT_EQ(corner_piece_defect(boxes({{{-2, -2, -2}, kO}}), {-1, -1, -1}), std::nullopt);
}

TEST(CornerPiece, WrongPiecesAreRefused) {
    // in the wrong octant
    EXPECT_NE(corner_piece_defect(boxes({{{-2, 0, 0}, {0, 2, 2}}}), kPlus), std::nullopt);
    // two cells
    EXPECT_NE(corner_piece_defect(boxes({{kO, {1, 2, 2}}, {{1, 0, 0}, kTwo}}), kPlus), std::nullopt);
    // the face z = 0 split through v: a fourth edge at v, off the half-axes
    EXPECT_NE(corner_piece_defect(boxes({{kO, kTwo}}, {{.split_face = 4}}), kPlus), std::nullopt);
    // v not a vertex
    EXPECT_NE(corner_piece_defect(boxes({{{1, 1, 1}, kTwo}}), kPlus), std::nullopt);
}

TEST(CornerQuadrant, TwoCubesAcrossAQuadrantPass) {
    EXPECT_EQ(corner_quadrant_defect(boxes({{kO, kTwo}, {{-2, 0, 0}, {0, 2, 2}}})), std::nullopt);
}

TEST(CornerQuadrant, WrongPairsAreRefused) {
    const std::pair<LatticePoint, LatticePoint> plus{kO, kTwo}, minus{{-2, 0, 0}, {0, 2, 2}};
    // the -x cube's face x = 0 split: the two faces at v on the quadrant differ
    EXPECT_NE(corner_quadrant_defect(boxes({plus, minus}, {{}, {.split_face = 1}})), std::nullopt);
    // a larger -x cube: its edges along +y and +z end elsewhere
    EXPECT_NE(corner_quadrant_defect(boxes({plus, {{-4, 0, 0}, {0, 4, 4}}})), std::nullopt);
    // the -x cube inward: the common face used with the same side by both
    EXPECT_NE(corner_quadrant_defect(boxes({plus, minus}, {{}, {.inward = true}})), std::nullopt);
}

}  // namespace
}  // namespace dualhex

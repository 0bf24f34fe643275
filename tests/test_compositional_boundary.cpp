// The root boundary (checkers/compositional_boundary.hpp): both root policies pass every
// boundary window under the strong rule; wrong rules, broken policies and wrong boundary
// cells are caught.
#include <gtest/gtest.h>

#include "dualhex/checkers/boundary_certificates.hpp"
#include "dualhex/checkers/compositional_boundary.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "test_wrong_rules.hpp"
#include "dualhex/topology/complex_builder.hpp"
#include "dualhex/topology/primitives.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex {
namespace {

const ElementLibrary& library() {
    static const ElementLibrary lib = ElementLibrary::load_default();
    return lib;
}

TEST(RootBoundary, StrongRuleEveryPolicy) {
    for (BoundaryPolicy policy : {BoundaryPolicy::Coarse, BoundaryPolicy::Mirror, BoundaryPolicy::AnyOutside}) {
        const BoundaryResult r = run_compositional_boundary(StrongRule(), library(), policy);
        for (const auto& f : r.failures) ADD_FAILURE() << r.policy << ": " << f;
        EXPECT_EQ(r.types.size(), 56u);
        for (const auto& t : r.types) {
            EXPECT_EQ(t.leaves, 8 >> t.planes);  // the inside leaves of B(g)
            EXPECT_EQ(t.passed, t.windows);
            EXPECT_GT(t.checked_vertices, 0u);
        }
        for (std::size_t k = 0; k < 3; ++k) EXPECT_GT(r.checked_vertices[k], 0u) << k;  // faces, edges, corners
        // pinned: a change of the rule or the enumeration shows here
        EXPECT_EQ(r.windows, policy == BoundaryPolicy::AnyOutside ? 14270u : 1684u);
        EXPECT_TRUE(r.all_passed());
    }
}

TEST(RootBoundary, WrongRulesAreCaught) {
    BoundaryOptions stop;
    stop.stop_after_failures = 1;
    for (test::WrongChoiceMode mode : {test::WrongChoiceMode::MisorientedE, test::WrongChoiceMode::MissingF})
        for (BoundaryPolicy policy : {BoundaryPolicy::Coarse, BoundaryPolicy::Mirror}) {
            const BoundaryResult r = run_compositional_boundary(test::WrongChoice(mode), library(), policy, stop);
            EXPECT_FALSE(r.all_passed()) << static_cast<int>(mode);
            EXPECT_FALSE(r.failures.empty()) << static_cast<int>(mode);
        }
}

// Any policy that is a function of the outside cube is a special case of AnyOutside (which
// passes), so a broken policy is one whose readers disagree about one outside cube: here
// fine for leaves with an even min corner y, coarse for the others.
TEST(RootBoundary, BrokenPoliciesAreCaught) {
    BoundaryOptions split;
    split.policy = [](const std::array<std::int64_t, 3>&, const RootSides&, const LatticePoint& reader) {
        return OutsideOctant{reader.y % 2 == 0 ? OutsideOctant::Kind::Fine : OutsideOctant::Kind::Coarse, {}};
    };
    const BoundaryResult r = run_compositional_boundary(StrongRule(), library(), BoundaryPolicy::Mirror, split);
    EXPECT_FALSE(r.all_passed());
    EXPECT_FALSE(r.failures.empty());
}

// Hand-made half windows: cubes of edge 1 filling [0,2] x [-2,2]^2 (root plane x = 0,
// 9 vertices on it strictly inside), with one cube at the root plane changed.
enum class Change { None, Prisms, Reversed, Removed };

// A convex cell's loops, each turned to face outward (the cell's centroid is behind it).
std::vector<std::vector<LatticePoint>> outward(std::vector<std::vector<LatticePoint>> loops) {
    LatticePoint sum{0, 0, 0};
    std::int64_t n = 0;
    for (const auto& l : loops)
        for (const auto& p : l) sum = sum + p, ++n;
    for (auto& l : loops) {
        const LatticePoint u = l[1] - l[0], w = l[2] - l[0];
        const LatticePoint normal{u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};
        const LatticePoint d = l[0] * n - sum;  // n * (vertex - centroid)
        if (normal.x * d.x + normal.y * d.y + normal.z * d.z < 0) std::reverse(l.begin(), l.end());
    }
    return loops;
}

CellComplex half_box(Change change) {
    ComplexBuilder b;
    for (int x = 0; x < 2; ++x)
        for (int y = -2; y < 2; ++y)
            for (int z = -2; z < 2; ++z) {
                const LatticePoint c{x, y, z};
                const bool changed = x == 0 && y == 0 && z == 0;
                if (!changed || change == Change::None) {
                    b.add_cell_from_loops(cube_loops(c));
                } else if (change == Change::Reversed) {
                    auto loops = cube_loops(c);
                    for (auto& l : loops) std::reverse(l.begin(), l.end());
                    b.add_cell_from_loops(loops);
                } else if (change == Change::Prisms) {  // split by the plane y = z
                    const auto p = [&](int dx, int dy, int dz) { return c + LatticePoint{dx, dy, dz}; };
                    b.add_cell_from_loops(outward({{p(0, 0, 0), p(0, 1, 0), p(0, 1, 1)}, {p(1, 0, 0), p(1, 1, 0), p(1, 1, 1)},
                                                   {p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 1, 0)},
                                                   {p(0, 1, 0), p(1, 1, 0), p(1, 1, 1), p(0, 1, 1)},
                                                   {p(0, 0, 0), p(0, 1, 1), p(1, 1, 1), p(1, 0, 0)}}));
                    b.add_cell_from_loops(outward({{p(0, 0, 0), p(0, 1, 1), p(0, 0, 1)}, {p(1, 0, 0), p(1, 1, 1), p(1, 0, 1)},
                                                   {p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1)},
                                                   {p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)},
                                                   {p(0, 0, 0), p(0, 1, 1), p(1, 1, 1), p(1, 0, 0)}}));
                }
            }
    return std::move(b).build();
}

TEST(RootBoundaryCheck, PlainCubesPassAndEachChangeFails) {
    const RootSides x_low{1, 0, 0};
    const BoundaryVertexReport plain = check_boundary_vertices(half_box(Change::None), 2, x_low);
    EXPECT_TRUE(plain.ok()) << (plain.failures.empty() ? "" : plain.failures.front());
    EXPECT_EQ(plain.checked, 9u);
    for (Change c : {Change::Prisms, Change::Reversed, Change::Removed}) {
        const BoundaryVertexReport r = check_boundary_vertices(half_box(c), 2, x_low);
        EXPECT_FALSE(r.ok()) << static_cast<int>(c);
        EXPECT_EQ(r.checked, 9u);
    }
}

// The certificates' doubling (boundary_certificates.hpp): the plain half box reflected across
// x = 0 is the valid box of 4^3 cubes; the inverted cube's copy stays inverted.
TEST(RootBoundaryCheck, DoublingReflectsAcrossTheRootPlanes) {
    const CellComplex doubled = double_half_window(half_box(Change::None), {1, 0, 0});
    EXPECT_EQ(doubled.n_cells(), 64u);
    EXPECT_EQ(doubled.n_vertices(), 125u);  // welded on the plane
    const ValidationReport r = validate(doubled);
    EXPECT_TRUE(r.ok());
    EXPECT_GT(r.checked_vertices, 0u);
    for (const LatticePoint& p : doubled.positions()) EXPECT_TRUE(-2 <= p.x && p.x <= 2) << p.x;
    EXPECT_FALSE(validate(double_half_window(half_box(Change::Reversed), {1, 0, 0})).ok());
    EXPECT_EQ(double_half_window(half_box(Change::None), {1, 1, 0}).n_cells(), 128u);  // 4 copies of 32
}

TEST(RootBoundaryCheck, HexOrientationIsExact) {
    std::array<RationalCorner, 8> unit;  // VTK order: bottom 0-3 counter-clockwise from above
    const int xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 8; ++i) unit[static_cast<std::size_t>(i)] = {{xy[i % 4][0] * 3, xy[i % 4][1] * 3, i / 4 * 3}, 3};
    EXPECT_TRUE(hex_positively_oriented(unit));
    std::array<RationalCorner, 8> flipped = unit;  // top and bottom swapped: inside out
    for (int i = 0; i < 4; ++i) std::swap(flipped[static_cast<std::size_t>(i)], flipped[static_cast<std::size_t>(i + 4)]);
    EXPECT_FALSE(hex_positively_oriented(flipped));
    std::array<RationalCorner, 8> flat = unit;  // zero volume
    for (int i = 4; i < 8; ++i) flat[static_cast<std::size_t>(i)].sum[2] = 0;
    EXPECT_FALSE(hex_positively_oriented(flat));
}

}  // namespace
}  // namespace dualhex

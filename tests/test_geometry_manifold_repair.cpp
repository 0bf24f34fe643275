// Manifold repair of a cell selection (manifold_repair.hpp): hand-made edge, vertex and
// hanging-hex defects must be detected and repaired on the side the score prefers;
// unrepairable ones must be reported. A RapidCheck property on random selections of a
// small block compares the result with check_hex_topology and with an independent
// lattice oracle (digital well-composedness: at every lattice vertex, the selected and
// the unselected cells of its 2 x 2 x 2 neighbourhood are each face-connected).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "dualhex/geometry/manifold_repair.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex::geometry;
using namespace geometry_test;

namespace {

// Flags of the cells (i, j, k) of `b` for which keep holds.
std::vector<char> flags(const HexBlock& b, const std::function<bool(int, int, int)>& keep) {
    std::vector<char> out(b.mesh.hexes.size(), 0);
    for (int k = 0; k < b.nz; ++k)
        for (int j = 0; j < b.ny; ++j)
            for (int i = 0; i < b.nx; ++i) out[static_cast<std::size_t>(b.cell(i, j, k))] = keep(i, j, k);
    return out;
}

// +inside for selected cells, outside for the others.
std::vector<double> scores(const std::vector<char>& selected, double inside, double outside) {
    std::vector<double> out;
    for (char s : selected) out.push_back(s ? inside : outside);
    return out;
}

HexTopology topology_of(const HexBlock& b, const std::vector<char>& selected) {
    return check_hex_topology(selected_mesh(b.mesh, selected));
}

// The oracle: is the boundary of the selection (cells outside the block count as
// unselected) a 2-manifold? At each lattice vertex the 8 cells around it form the graph
// of a cube (face adjacency = differing in one axis); both the selected and the
// unselected ones must be connected in it.
bool lattice_manifold(const HexBlock& b, const std::vector<char>& selected) {
    auto in = [&](int i, int j, int k) {
        return i >= 0 && j >= 0 && k >= 0 && i < b.nx && j < b.ny && k < b.nz &&
               selected[static_cast<std::size_t>(b.cell(i, j, k))];
    };
    for (int z = 0; z <= b.nz; ++z)
        for (int y = 0; y <= b.ny; ++y)
            for (int x = 0; x <= b.nx; ++x) {
                int occupied = 0;  // bit o: octant o = (dx, dy, dz) bits
                for (int o = 0; o < 8; ++o)
                    occupied |= in(x - 1 + (o & 1), y - 1 + (o >> 1 & 1), z - 1 + (o >> 2 & 1)) << o;
                for (int part : {occupied, ~occupied & 0xff}) {
                    if (part == 0) continue;
                    int reached = part & -part;  // flood fill from the lowest octant
                    for (int step = 0; step < 8; ++step)
                        for (int o = 0; o < 8; ++o)
                            if (reached >> o & 1)
                                for (int axis : {1, 2, 4}) reached |= (1 << (o ^ axis)) & part;
                    if (reached != part) return false;
                }
            }
    return true;
}

ManifoldRepairResult repair(const HexBlock& b, const std::vector<char>& selected, const std::vector<double>& score,
                            const ManifoldRepairOptions& options = {}) {
    return repair_manifold_selection(b.mesh.hexes, b.mesh.points.size(), selected, score, options);
}

}  // namespace

TEST(ManifoldRepair, OracleAgreesWithTheCheckerOnHandMadeCases) {
    const HexBlock b = hex_block(2, 2, 2);
    const auto edge = flags(b, [](int i, int j, int k) { return k == 0 && i == j; });
    const auto vertex = flags(b, [](int i, int j, int k) { return i == j && j == k; });
    const auto cones = flags(b, [](int i, int j, int k) { return !(i == j && j == k); });
    const auto slab = flags(b, [](int, int, int k) { return k == 0; });
    for (const auto* s : {&edge, &vertex, &cones}) {
        EXPECT_FALSE(lattice_manifold(b, *s));
        EXPECT_FALSE(topology_of(b, *s).valid());
    }
    EXPECT_TRUE(lattice_manifold(b, slab));
    EXPECT_TRUE(topology_of(b, slab).valid());
}

TEST(ManifoldRepair, DiagonalEdgeIsFilledWhenAddingIsCheaper) {
    const HexBlock b = hex_block(2, 2, 1);
    const auto sel = flags(b, [](int i, int j, int) { return i == j; });
    ASSERT_EQ(topology_of(b, sel).non_manifold_edges, 1u);  // detected before the repair
    const auto r = repair(b, sel, scores(sel, 1.0, -0.5));
    ASSERT_TRUE(r.manifold()) << topology_of(b, r.selected).summary();
    ASSERT_EQ(r.changes.size(), 1u);
    EXPECT_TRUE(r.changes[0].selected);
    EXPECT_EQ(r.changes[0].cell, static_cast<std::size_t>(b.cell(1, 0, 0)));  // tie: the smaller index
    EXPECT_EQ(r.changes[0].spot, DefectSpot::Edge);
    EXPECT_TRUE(topology_of(b, r.selected).valid());
}

TEST(ManifoldRepair, DiagonalEdgeIsCutWhenRemovingIsCheaper) {
    const HexBlock b = hex_block(2, 2, 1);
    auto sel = flags(b, [](int i, int j, int) { return i == j; });
    auto score = scores(sel, 1.0, -1.0);
    score[static_cast<std::size_t>(b.cell(1, 1, 0))] = 0.1;  // barely inside
    const auto r = repair(b, sel, score);
    ASSERT_TRUE(r.manifold());
    ASSERT_EQ(r.changes.size(), 1u);
    EXPECT_FALSE(r.changes[0].selected);
    EXPECT_EQ(r.changes[0].cell, static_cast<std::size_t>(b.cell(1, 1, 0)));
    EXPECT_EQ(topology_of(b, r.selected).hexes, 1u);
}

TEST(ManifoldRepair, VertexContactsAreRepaired) {
    const HexBlock b = hex_block(2, 2, 2);
    const auto sel = flags(b, [](int i, int j, int k) { return i == j && j == k; });
    ASSERT_EQ(topology_of(b, sel).non_manifold_vertices, 1u);
    const auto grown = repair(b, sel, scores(sel, 1.0, -0.2));  // adding is cheaper: grows
    EXPECT_TRUE(grown.manifold());
    EXPECT_TRUE(topology_of(b, grown.selected).valid());
    EXPECT_TRUE(lattice_manifold(b, grown.selected));
    EXPECT_GT(std::count(grown.selected.begin(), grown.selected.end(), 1), 2);
    const auto cones = flags(b, [](int i, int j, int k) { return !(i == j && j == k); });
    const auto filled = repair(b, cones, scores(cones, 1.0, -0.2));
    ASSERT_TRUE(filled.manifold());
    ASSERT_EQ(filled.changes.size(), 1u);  // one of the two missing cells added back
    EXPECT_EQ(filled.changes[0].spot, DefectSpot::Vertex);
    EXPECT_EQ(filled.changes[0].at[0], 13);  // the centre vertex (1,1,1) of the 3^3 lattice
}

TEST(ManifoldRepair, HangingHexIsRemovedWhenItIsBarelyInside) {
    const HexBlock b = hex_block(3, 3, 3);
    auto sel = flags(b, [](int i, int, int k) { return k == 0 && i < 2; });
    const std::size_t hanging = static_cast<std::size_t>(b.cell(2, 0, 1));  // edge contact at x = 2, z = 1
    sel[hanging] = 1;
    auto score = scores(sel, 1.0, -1.0);
    score[hanging] = 0.05;
    const auto before = topology_of(b, sel);
    ASSERT_EQ(before.non_manifold_edges, 1u);
    ASSERT_EQ(before.hex_components, 2u);
    const auto r = repair(b, sel, score);
    ASSERT_TRUE(r.manifold());
    EXPECT_FALSE(r.selected[hanging]);
    const auto after = topology_of(b, r.selected);
    EXPECT_TRUE(after.valid());
    EXPECT_EQ(after.hex_components, 1u);
    EXPECT_EQ(after.hexes, 6u);
}

TEST(ManifoldRepair, UnrepairableDefectsAreReported) {
    // Two hexes meeting along an edge are the whole complex: nothing to add, and removing
    // is not allowed.
    const HexBlock b = hex_block(2, 2, 1);
    const auto sel = flags(b, [](int i, int j, int) { return i == j; });
    std::vector<std::array<int, 8>> cells;
    std::vector<char> both;
    for (std::size_t c = 0; c < sel.size(); ++c)
        if (sel[c]) {
            cells.push_back(b.mesh.hexes[c]);
            both.push_back(1);
        }
    ManifoldRepairOptions no_removal;
    no_removal.may_remove = false;
    const auto r = repair_manifold_selection(cells, b.mesh.points.size(), both, {1.0, 1.0}, no_removal);
    EXPECT_FALSE(r.manifold());
    EXPECT_TRUE(r.changes.empty());
    EXPECT_EQ(r.remaining.non_manifold_edges.size(), 1u);
    EXPECT_FALSE(r.hit_round_limit);
    // No rounds allowed: the defect is reported, not hidden.
    ManifoldRepairOptions none;
    none.max_rounds = 0;
    const auto s = repair(b, sel, scores(sel, 1.0, -0.5), none);
    EXPECT_FALSE(s.manifold());
    EXPECT_TRUE(s.hit_round_limit);
    EXPECT_EQ(s.selected, sel);
}

TEST(ManifoldRepair, BadInputIsRefused) {
    const HexBlock b = hex_block(2, 1, 1);
    EXPECT_THROW((void)repair(b, {1}, {1.0, 1.0}), std::invalid_argument);
    EXPECT_THROW((void)repair(b, {1, 0}, {1.0, std::nan("")}), std::invalid_argument);
    auto cells = b.mesh.hexes;
    cells[1][2] = -1;
    EXPECT_THROW((void)repair_manifold_selection(cells, b.mesh.points.size(), {1, 1}, {1.0, 1.0}),
                 std::invalid_argument);
}

RC_GTEST_PROP(ManifoldRepair, RandomSelectionsEndManifoldAndTheCheckersAgree, ()) {
    const int n = *rc::gen::inRange(2, 5);
    const HexBlock b = hex_block(n, n, n);
    const auto m = b.mesh.hexes.size();
    const auto sel = *rc::gen::container<std::vector<char>>(m, rc::gen::element(char{0}, char{1}));
    const auto raw = *rc::gen::container<std::vector<int>>(m, rc::gen::inRange(-100, 101));
    std::vector<double> score;
    for (int s : raw) score.push_back(s / 100.0);
    ManifoldRepairOptions options;
    options.may_remove = *rc::gen::arbitrary<bool>();
    // before: the oracle and the checker agree
    RC_ASSERT(lattice_manifold(b, sel) == topology_of(b, sel).valid());
    const auto r = repair(b, sel, score, options);
    RC_CLASSIFY(r.changes.empty(), "no change needed");
    RC_CLASSIFY(r.changes.size() > 5, "more than 5 changes");
    // the changes replayed on the input give the output
    auto replay = sel;
    for (const auto& c : r.changes) replay[c.cell] = c.selected;
    RC_ASSERT(replay == r.selected);
    // after: the repair, the checker and the oracle agree, and a block always ends manifold
    const auto t = topology_of(b, r.selected);
    RC_ASSERT(r.manifold() == t.valid());
    RC_ASSERT(t.valid() == lattice_manifold(b, r.selected));
    RC_ASSERT(r.manifold());
    RC_ASSERT(!r.hit_round_limit);
}

// Topology-controlled core growth (mesher/core_topology.hpp) on hand-made selections whose
// topology is known: a ring of 8 hexes (a solid torus), blocks, two separate parts.
#include <gtest/gtest.h>

#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/mesher/core_topology.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using namespace geometry_test;

namespace {

std::vector<std::array<int, 8>> cells_of(const geometry::HexMesh& m) {
    std::vector<std::array<int, 8>> out;
    for (const auto& h : m.hexes) out.push_back({h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7]});
    return out;
}

struct Grown {
    std::size_t hexes = 0;
    std::vector<std::int64_t> chi;  // boundary components' Euler characteristics
};

// Grows from the selection `keep` of block b (score: -distance from cell `deepest`).
Grown grow(const HexBlock& b, const std::vector<char>& keep, std::size_t parts, std::size_t handles,
           int deepest = 0) {
    const auto cells = cells_of(b.mesh);
    std::vector<double> score(cells.size());
    for (std::size_t h = 0; h < cells.size(); ++h) score[h] = -std::abs(static_cast<double>(h) - deepest);
    const std::vector<char> in =
        mesher::grow_core_with_topology(cells, b.mesh.points.size(), keep, score, parts, handles);
    Grown g;
    for (std::size_t h = 0; h < in.size(); ++h) {
        EXPECT_TRUE(!in[h] || keep[h]) << "hex " << h << " grown outside the candidates";
        g.hexes += in[h] ? 1 : 0;
    }
    const auto topo = geometry::check_hex_topology(selected_mesh(b.mesh, in), 0);
    EXPECT_EQ(topo.non_manifold_edges + topo.non_manifold_vertices, 0u);
    for (const auto& c : topo.boundary_components) g.chi.push_back(c.euler());
    return g;
}

std::vector<char> flags(const HexBlock& b, bool (*keep)(int, int, int)) {
    std::vector<char> f(b.mesh.hexes.size(), 0);
    for (int k = 0; k < b.nz; ++k)
        for (int j = 0; j < b.ny; ++j)
            for (int i = 0; i < b.nx; ++i) f[static_cast<std::size_t>(b.cell(i, j, k))] = keep(i, j, k) ? 1 : 0;
    return f;
}

}  // namespace

TEST(CoreTopology, BlockGrowsWhole) {
    const HexBlock b = hex_block(3, 3, 3);
    const Grown g = grow(b, flags(b, [](int, int, int) { return true; }), 1, 0, 13);
    EXPECT_EQ(g.hexes, 27u);
    EXPECT_EQ(g.chi, (std::vector<std::int64_t>{2}));
}

TEST(CoreTopology, RingIsCutWithoutHandlesAndKeptWithOne) {
    const HexBlock b = hex_block(3, 3, 1);
    const auto ring = flags(b, [](int i, int j, int) { return !(i == 1 && j == 1); });
    const Grown cut = grow(b, ring, 1, 0);
    EXPECT_EQ(cut.hexes, 7u);  // one hex of the ring left out: a ball
    EXPECT_EQ(cut.chi, (std::vector<std::int64_t>{2}));
    const Grown kept = grow(b, ring, 1, 1);
    EXPECT_EQ(kept.hexes, 8u);  // the solid torus
    EXPECT_EQ(kept.chi, (std::vector<std::int64_t>{0}));
}

TEST(CoreTopology, EdgeContactIsNotGrownThrough) {
    // Two 2x2x1 slabs of a 4x4x1 block meeting only along an edge of cells (1,1)/(2,2):
    // growing from one may not take the other through the edge, and growing both leaves out
    // one of the two cells at the edge (together they would make a non-manifold edge).
    const HexBlock b = hex_block(4, 4, 1);
    const auto two = flags(b, [](int i, int j, int) { return (i < 2 && j < 2) || (i >= 2 && j >= 2); });
    const Grown one_part = grow(b, two, 1, 0);
    EXPECT_EQ(one_part.hexes, 4u);
    const Grown both = grow(b, two, 2, 0, 15);
    EXPECT_EQ(both.hexes, 7u);
    EXPECT_EQ(both.chi, (std::vector<std::int64_t>{2, 2}));
}

TEST(CoreTopology, CavityIsNotClosed) {
    // A hollow 3x3x3 block: the shell's outer boundary and the cavity's (chi 2 + 2); grown
    // without handles the last shell hex would close the cavity, so it is left out.
    const HexBlock b = hex_block(3, 3, 3);
    const auto shell = flags(b, [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); });
    const Grown g = grow(b, shell, 1, 0);
    EXPECT_EQ(g.hexes, 25u);
    EXPECT_EQ(g.chi, (std::vector<std::int64_t>{2}));
}

namespace {

// Grows from `keep` through `fill` (both flags of block b), as the core stage does.
Grown grow_filled(const HexBlock& b, const std::vector<char>& keep, const std::vector<char>& fill, std::size_t parts,
                  std::size_t handles, std::vector<char>* result = nullptr) {
    const auto cells = cells_of(b.mesh);
    std::vector<double> score(cells.size(), 0.0);
    const std::vector<char> in =
        mesher::grow_core_with_topology(cells, b.mesh.points.size(), keep, fill, score, parts, handles);
    Grown g;
    for (std::size_t h = 0; h < in.size(); ++h) {
        EXPECT_TRUE(!in[h] || keep[h] || fill[h]) << "hex " << h << " grown outside candidates and fill";
        g.hexes += in[h] ? 1 : 0;
    }
    const auto topo = geometry::check_hex_topology(selected_mesh(b.mesh, in), 0);
    EXPECT_EQ(topo.non_manifold_edges + topo.non_manifold_vertices, 0u);
    for (const auto& c : topo.boundary_components) g.chi.push_back(c.euler());
    if (result) *result = in;
    return g;
}

}  // namespace

TEST(CoreTopology, TunnelIsFilledNotCut) {
    // The ring of 8 with its hole a fill hex: without fill one ring hex is cut (7); with the
    // hole as fill the tunnel is closed instead, and the whole ring stays (9, a ball).
    const HexBlock b = hex_block(3, 3, 1);
    const auto ring = flags(b, [](int i, int j, int) { return !(i == 1 && j == 1); });
    const auto hole = flags(b, [](int i, int j, int) { return i == 1 && j == 1; });
    EXPECT_EQ(grow_filled(b, ring, {}, 1, 0).hexes, 7u);
    std::vector<char> in;
    const Grown filled = grow_filled(b, ring, hole, 1, 0, &in);
    EXPECT_EQ(filled.hexes, 9u);
    EXPECT_EQ(filled.chi, (std::vector<std::int64_t>{2}));
    EXPECT_TRUE(in[static_cast<std::size_t>(b.cell(1, 1, 0))]);
}

TEST(CoreTopology, ThinNeckJoinsAPartThroughFill) {
    // Two 2x1x1 parts of a 5x1x1 row, the middle cell fill: one part asked for, the neck
    // is kept and the far part joins (5); without fill only the seeded part grows (2).
    const HexBlock b = hex_block(5, 1, 1);
    const auto parts = flags(b, [](int i, int, int) { return i != 2; });
    const auto neck = flags(b, [](int i, int, int) { return i == 2; });
    EXPECT_EQ(grow_filled(b, parts, {}, 1, 0).hexes, 2u);
    const Grown joined = grow_filled(b, parts, neck, 1, 0);
    EXPECT_EQ(joined.hexes, 5u);
    EXPECT_EQ(joined.chi, (std::vector<std::int64_t>{2}));
}

TEST(CoreTopology, UnneededFillIsPeeled) {
    // A 3x3x3 candidate block inside a 5x5x5 block whose shell is fill: the growth runs
    // through the shell, and every shell hex is peeled again (the topology needs none).
    const HexBlock b = hex_block(5, 5, 5);
    const auto inner = flags(b, [](int i, int j, int k) { return i > 0 && i < 4 && j > 0 && j < 4 && k > 0 && k < 4; });
    const auto shell = flags(b, [](int i, int j, int k) { return !(i > 0 && i < 4 && j > 0 && j < 4 && k > 0 && k < 4); });
    const Grown g = grow_filled(b, inner, shell, 1, 0);
    EXPECT_EQ(g.hexes, 27u);
    EXPECT_EQ(g.chi, (std::vector<std::int64_t>{2}));
}

TEST(CoreTopology, PeelingKeepsAGenuineHandle) {
    // A ring of candidates that the input may keep as a handle (1 allowed), fill around it
    // on top: peeling the fill must not open or close anything (chi 0 stays).
    const HexBlock b = hex_block(3, 3, 2);
    const auto ring = flags(b, [](int i, int j, int k) { return k == 0 && !(i == 1 && j == 1); });
    const auto lid = flags(b, [](int i, int j, int k) { return k == 1 && !(i == 1 && j == 1); });
    const Grown g = grow_filled(b, ring, lid, 1, 1);
    EXPECT_EQ(g.hexes, 8u);
    EXPECT_EQ(g.chi, (std::vector<std::int64_t>{0}));
}

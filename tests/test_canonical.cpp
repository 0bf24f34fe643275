// The canonical summary (distributed/include/dualhex/distributed/canonical.hpp), serially:
// it adds up over any split of leaves and vertices, and it sees a one-leaf difference.
#include <gtest/gtest.h>

#include "dualhex/distributed/canonical_json.hpp"
#include "test_distributed_fixture.hpp"

namespace dualhex {
namespace {

using test::random_grid;
using test::root_dual;
using test::serial_install;

TEST(Canonical, SharedGridGivesThePublishedFigures) {
    const auto path = std::filesystem::path(DUALHEX_SHARED_DATA) / "grids/sphere_strong_d5.leaves";
    ASSERT_TRUE(std::filesystem::exists(path));
    const InstallResult r = serial_install(read_leaf_file(path), Balance::Strong);
    const Incidence inc(r.complex);
    const CanonicalSummary s = summarize(r, inc, root_dual(r, inc));
    EXPECT_EQ(s.cells, 13952U);  // the paper's published implementation on this file (README)
    EXPECT_EQ(s.non_hex_cells, 3608U);
    EXPECT_EQ(s.hexes, 14745U);
    EXPECT_EQ(s.vertices, r.complex.n_vertices());
    EXPECT_EQ(s.non_cube_vertices, 0U);
    std::uint64_t faces = 0;
    for (const auto& [size, n] : s.face_sizes) faces += n;
    EXPECT_EQ(faces, r.complex.n_faces());
}

TEST(Canonical, PartsAddUpToTheWhole) {
    // Any split of leaves (a prefix) and of vertices (by a hash) sums to the whole summary:
    // what ranks do with their own leaves and owned vertices.
    const InstallResult r = serial_install(pair(random_grid(7, 4, 0.3), Balance::Weak), Balance::Weak);
    const Incidence inc(r.complex);
    const ClippedDual d = root_dual(r, inc);
    const CanonicalSummary whole = summarize(r, inc, d);
    const std::size_t n_leaves = r.leaf_cells.size() - 1, cut = n_leaves / 3;
    const auto odd = [](VertexHandle v) { return (mix64(v.index()) & 1U) != 0; };
    CanonicalSummary a = summarize(r, inc, d, {0, cut, odd});
    const CanonicalSummary b = summarize(r, inc, d, {cut, n_leaves, [&](VertexHandle v) { return !odd(v); }});
    a.add(b);
    EXPECT_EQ(a, whole);
    EXPECT_GT(whole.hexes, 100U);
}

TEST(Canonical, OneLeafMoreChangesBothHashes) {
    const LeafGrid g = pair(random_grid(3, 4, 0.3), Balance::Strong);
    std::vector<Leaf> leaves = g.leaves();
    // Split a coarse leaf of the paired grid: it stays subdivided whatever pairing and
    // balancing add, so the grid differs.
    const auto it = std::find_if(leaves.begin(), leaves.end(), [](const Leaf& l) { return l.level < 3; });
    ASSERT_NE(it, leaves.end());
    const Leaf split = *it;
    leaves.erase(it);
    for (const Leaf& c : children(split)) leaves.push_back(c);
    const CanonicalSummary s0 = test::serial_summary(g, Balance::Strong), s1 = test::serial_summary(LeafGrid(leaves), Balance::Strong);
    EXPECT_NE(s0.hex_hash, s1.hex_hash);
    EXPECT_NE(s0.cell_hash, s1.cell_hash);
}

TEST(Canonical, JsonRoundTrips) {
    const CanonicalSummary s = test::serial_summary(random_grid(11, 3, 0.4), Balance::Weak);
    EXPECT_EQ(summary_from_json(to_json(s)), s);
    EXPECT_EQ(hash_hex(0xfULL), "000000000000000f");
}

}  // namespace
}  // namespace dualhex

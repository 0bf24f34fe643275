// The core cleanup before the pad (mesher/core_cleanup.hpp) on hand-made selections of a
// block of unit hexes: spikes, ridges and notches one hex wide are cleaned, flips that would
// change the topology (a ring's hexes, its hole) are refused, the result is a fixed point;
// and in the pipeline on the default torus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/mesher/core_cleanup.hpp"
#include "dualhex/mesher/core_topology.hpp"
#include "dualhex/mesher/default_shape.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using namespace geometry_test;

namespace {

using Pick = std::function<bool(int, int, int)>;

std::vector<std::array<int, 8>> cells_of(const geometry::HexMesh& m) { return {m.hexes.begin(), m.hexes.end()}; }

std::vector<char> picked(const HexBlock& b, const Pick& keep) {
    std::vector<char> f(b.mesh.hexes.size(), 0);
    for (int k = 0; k < b.nz; ++k)
        for (int j = 0; j < b.ny; ++j)
            for (int i = 0; i < b.nx; ++i) f[static_cast<std::size_t>(b.cell(i, j, k))] = keep(i, j, k) ? 1 : 0;
    return f;
}

struct Boundary {
    std::size_t non_manifold = 0;
    std::vector<std::int64_t> chi;
};

Boundary boundary_of(const HexBlock& b, const std::vector<char>& in) {
    const auto t = geometry::check_hex_topology(selected_mesh(b.mesh, in), 0);
    Boundary out{t.non_manifold_edges + t.non_manifold_vertices, {}};
    for (const auto& c : t.boundary_components) out.chi.push_back(c.euler());
    return out;
}

// Per hex of `in`'s side: its faces on the other side (core_cleanup's definition, recomputed
// here by brute force on the block's (i, j, k) grid: kHexFaces are z-, z+, y-, x+, y+, x-).
unsigned other_faces(const HexBlock& b, const std::vector<char>& in, int i, int j, int k) {
    const std::array<std::array<int, 3>, 6> step{{{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}}};
    const bool self = in[static_cast<std::size_t>(b.cell(i, j, k))] != 0;
    unsigned bits = 0;
    for (std::size_t f = 0; f < 6; ++f) {
        const int x = i + step[f][0], y = j + step[f][1], z = k + step[f][2];
        const bool inside = x >= 0 && y >= 0 && z >= 0 && x < b.nx && y < b.ny && z < b.nz;
        const bool other = inside && in[static_cast<std::size_t>(b.cell(x, y, z))] != 0;
        if (other != self) bits |= 1u << f;
    }
    return bits;
}

std::size_t exposed_count(const HexBlock& b, const std::vector<char>& in, const std::vector<char>& candidates) {
    std::size_t n = 0;
    for (int k = 0; k < b.nz; ++k)
        for (int j = 0; j < b.ny; ++j)
            for (int i = 0; i < b.nx; ++i)
                if (candidates[static_cast<std::size_t>(b.cell(i, j, k))] && mesher::exposed_faces(other_faces(b, in, i, j, k)))
                    ++n;
    return n;
}

}  // namespace

TEST(CoreCleanup, ExposedFaces) {
    EXPECT_FALSE(mesher::exposed_faces(0));
    EXPECT_FALSE(mesher::exposed_faces(0b000011));  // two opposite faces: a slab, left to the simple test
    EXPECT_FALSE(mesher::exposed_faces(0b001001));  // a convex edge
    EXPECT_FALSE(mesher::exposed_faces(0b001101));  // z-, y-, x+: a corner of the staircase
    EXPECT_TRUE(mesher::exposed_faces(0b010101));   // z-, y-, y+: a ridge (U)
    EXPECT_TRUE(mesher::exposed_faces(0b101010));   // z+, x+, x-: a ridge (U)
    EXPECT_TRUE(mesher::exposed_faces(0b001111));   // four faces
    EXPECT_TRUE(mesher::exposed_faces(0b111110));   // a spike
}

// A 4 x 4 x 2 box in a 6 x 6 x 4 block, with a spike on top, a ridge 3 hexes long on top,
// a notch (a missing top hex inside the top layer) and a missing top corner hex: the spike
// and the ridge go, the notch is filled, the missing corner (an ordinary concave corner)
// stays but the hex under it, left with 4 faces out, goes too.
TEST(CoreCleanup, StaircaseIsCleaned) {
    const HexBlock b = hex_block(6, 6, 4);
    const Pick box = [](int i, int j, int k) { return i >= 1 && i <= 4 && j >= 1 && j <= 4 && k >= 1 && k <= 2; };
    const Pick with_defects = [&](int i, int j, int k) {
        if (i == 1 && j == 1 && k == 3) return true;          // spike (5 faces out)
        if (i == 3 && j >= 2 && j <= 4 && k == 3) return true;  // ridge along y
        if (i == 4 && j == 1 && k == 2) return false;         // missing corner
        if (i == 2 && j == 3 && k == 2) return false;         // notch in the top layer (5 core faces)
        return box(i, j, k);
    };
    const std::vector<char> in = picked(b, with_defects);
    const std::vector<char> all(in.size(), 1);
    ASSERT_GT(exposed_count(b, in, all), 0u);
    EXPECT_EQ(boundary_of(b, in).chi, (std::vector<std::int64_t>{2}));

    const mesher::CoreCleanup c = mesher::clean_core(cells_of(b.mesh), b.mesh.points.size(), in, all);
    EXPECT_EQ(c.removed, 5u);  // the spike, the ridge, the hex under the missing corner
    EXPECT_EQ(c.added, 1u);    // the notch
    EXPECT_EQ(c.refused, 0u);
    EXPECT_EQ(exposed_count(b, c.in, all), 0u) << "not a fixed point";
    const Boundary after = boundary_of(b, c.in);
    EXPECT_EQ(after.non_manifold, 0u);
    EXPECT_EQ(after.chi, (std::vector<std::int64_t>{2}));
    EXPECT_EQ(c.in, picked(b, [&](int i, int j, int k) { return box(i, j, k) && !(i == 4 && j == 1); }));
    // Deterministic: the same input gives the same selection.
    EXPECT_EQ(mesher::clean_core(cells_of(b.mesh), b.mesh.points.size(), in, all).in, c.in);
}

// Only flippable hexes flip: with only the core's own hexes flippable (may leave, none may
// join) the notch in a 5 x 5 x 2 box stays (its neighbours have 2 faces out, not exposed).
TEST(CoreCleanup, NotchNotAddableStays) {
    const HexBlock b = hex_block(7, 7, 4);
    const std::vector<char> in = picked(b, [](int i, int j, int k) {
        return i >= 1 && i <= 5 && j >= 1 && j <= 5 && k >= 1 && k <= 2 && !(i == 3 && j == 3 && k == 2);
    });
    const mesher::CoreCleanup c = mesher::clean_core(cells_of(b.mesh), b.mesh.points.size(), in, in);
    EXPECT_EQ(c.added + c.removed, 0u);
    EXPECT_EQ(c.in, in);
    // In a 3 x 3 x 2 box the notch's four neighbours are walls one hex wide (U): without
    // the notch filled they go, and then the top corners they leave as spikes (5 faces out);
    // the slab below (its rim hexes now exposed) is not eroded further: only hexes exposed
    // at the start, and spikes, flip.
    const HexBlock s = hex_block(5, 5, 4);
    const std::vector<char> small = picked(s, [](int i, int j, int k) {
        return i >= 1 && i <= 3 && j >= 1 && j <= 3 && k >= 1 && k <= 2 && !(i == 2 && j == 2 && k == 2);
    });
    const mesher::CoreCleanup e = mesher::clean_core(cells_of(s.mesh), s.mesh.points.size(), small, small);
    EXPECT_EQ(e.removed, 8u);
    EXPECT_EQ(e.in, picked(s, [](int i, int j, int k) { return i >= 1 && i <= 3 && j >= 1 && j <= 3 && k == 1; }));
    EXPECT_EQ(boundary_of(s, e.in).chi, (std::vector<std::int64_t>{2}));
    // With nothing flippable nothing changes; with every hex flippable the notch is filled
    // instead and nothing is removed.
    const mesher::CoreCleanup none = mesher::clean_core(cells_of(s.mesh), s.mesh.points.size(), small,
                                                        std::vector<char>(small.size(), 0));
    EXPECT_EQ(none.in, small);
    const mesher::CoreCleanup f = mesher::clean_core(cells_of(s.mesh), s.mesh.points.size(), small,
                                                     std::vector<char>(small.size(), 1));
    EXPECT_EQ(f.added, 1u);
    EXPECT_EQ(f.removed, 0u);
}

// A ring of 8 hexes one hex thick (a solid torus, chi 0): every ring hex is exposed (4 faces
// out) and the hole is exposed (4 core faces), but removing a ring hex would cut the ring
// and filling the hole would close it: all refused, the ring unchanged.
TEST(CoreCleanup, TopologyChangingFlipsAreRefused) {
    const HexBlock b = hex_block(5, 5, 3);
    const Pick ring = [](int i, int j, int k) {
        return k == 1 && i >= 1 && i <= 3 && j >= 1 && j <= 3 && !(i == 2 && j == 2);
    };
    const std::vector<char> in = picked(b, ring);
    const std::vector<char> all(in.size(), 1);
    ASSERT_EQ(boundary_of(b, in).chi, (std::vector<std::int64_t>{0}));
    const mesher::CoreCleanup c = mesher::clean_core(cells_of(b.mesh), b.mesh.points.size(), in, all);
    EXPECT_EQ(c.removed + c.added, 0u);
    EXPECT_EQ(c.refused, 9u);  // 8 ring hexes, the hole
    EXPECT_EQ(c.in, in);
    EXPECT_EQ(boundary_of(b, c.in).chi, (std::vector<std::int64_t>{0}));
}

// The flip test itself: a spike may leave, a ring hex may not; flipping changes the selection.
TEST(CoreCleanup, SelectionFlips) {
    const HexBlock b = hex_block(5, 5, 3);
    std::vector<char> in = picked(b, [](int i, int j, int k) {
        return k == 1 && i >= 1 && i <= 3 && j >= 1 && j <= 3 && !(i == 2 && j == 2);
    });
    mesher::SelectionFlips flips(cells_of(b.mesh), b.mesh.points.size(), in);
    EXPECT_FALSE(flips.simple(b.cell(1, 1, 1)));  // a ring corner: the ring would be cut
    EXPECT_FALSE(flips.simple(b.cell(2, 2, 1)));  // the hole: the ring would be closed
    EXPECT_TRUE(flips.simple(b.cell(1, 1, 2)));   // on top of a ring hex: meets it in one face
    flips.flip(b.cell(1, 1, 2));
    EXPECT_TRUE(flips.in()[static_cast<std::size_t>(b.cell(1, 1, 2))]);
    EXPECT_TRUE(flips.simple(b.cell(1, 1, 2)));  // and may leave again
    EXPECT_FALSE(flips.simple(b.cell(1, 1, 1)));  // still: the hole touches it along an edge
}

// In the pipeline (select_core.hpp clean_core_selection) on the default torus (chi 0): with
// removal on, the core differs from the uncleaned one by exactly the flips counted, the
// fates name them, and the output's topology still matches the input's.
TEST(CoreCleanup, PipelineKeepsTheTorus) {
    const geometry::AabbTree tree(mesher::default_shape());
    mesher::MeshPipelineOptions options;
    options.max_depth = 5;
    options.core.cleanup = false;
    const mesher::MeshPipelineResult off = mesher::mesh_surface(tree, options);
    options.core.cleanup = true;
    options.core.cleanup_remove_depth = INFINITY;
    const mesher::MeshPipelineResult on = mesher::mesh_surface(tree, options);
    EXPECT_EQ(off.core.cleanup_removed + off.core.cleanup_added, 0u);
    EXPECT_GT(on.core.cleanup_removed + on.core.cleanup_added, 0u);
    EXPECT_FALSE(on.core.cleanup_reverted);
    EXPECT_EQ(on.core_hexes + on.core.cleanup_removed, off.core_hexes + on.core.cleanup_added);
    EXPECT_EQ(static_cast<std::size_t>(std::count(on.core.fate.begin(), on.core.fate.end(), mesher::CoreFate::CleanedOut)),
              on.core.cleanup_removed);
    EXPECT_EQ(static_cast<std::size_t>(std::count(on.core.fate.begin(), on.core.fate.end(), mesher::CoreFate::CleanedIn)),
              on.core.cleanup_added);
    EXPECT_TRUE(on.topology.matches);
    EXPECT_EQ(on.topology.euler, (std::vector<std::int64_t>{0}));
}

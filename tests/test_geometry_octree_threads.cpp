// The surface octree built in parallel (geometry/src/surface_octree_walk.cpp: the subtrees
// near the root walked by oneTBB tasks, concatenated in child order) is the serial
// recursion's octree leaf for leaf, in the same (Morton) order, with the same counts, under
// task arenas of 1, 2 and 4 threads; past the leaf budget it refuses exactly as the serial
// walk does (same message, same count), and just below the point where the parallel count
// gives up it returns what the serial walk returns.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "surface_octree_walk.hpp"
#include "test_geometry_fixture.hpp"
#include "sanitized.hpp"

namespace dualhex::geometry {
namespace {

using geometry_test::shared_surface;
using geometry_test::unit_cube_surface;

constexpr int kThreads[] = {1, 2, 4};

// Under AddressSanitizer the bunny is meshed at 2 % instead of 1 %.
using testing::kSanitized;

// What a walk gives: its leaves and counts, or its refusal.
struct Outcome {
    std::vector<Leaf> leaves;
    std::size_t crossing = 0, curvature_splits = 0;
    std::optional<std::string> refused;
    std::size_t refused_leaves = 0;
    bool operator==(const Outcome&) const = default;
};

template <class Walk>
Outcome outcome(Walk&& walk) {
    Outcome o;
    try {
        detail::WalkResult r = walk();
        o.leaves = std::move(r.leaves), o.crossing = r.crossing, o.curvature_splits = r.curvature_splits;
    } catch (const OctreeTooLarge& e) {
        o.refused = e.what(), o.refused_leaves = e.leaves();
    }
    return o;
}

// The serial walk and surface_octree's parallel one at 1, 2, 4 threads agree. Returns the
// serial outcome.
Outcome expect_same_as_serial(const AabbTree& tree, const SurfaceOctreeOptions& options, const char* what) {
    static const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
    const SurfaceRefinement criterion(tree, options);
    const Outcome serial = outcome([&] { return detail::serial_walk(criterion); });
    for (int t : kThreads) {
        Outcome parallel;
        tbb::task_arena(t).execute([&] { parallel = outcome([&] { return detail::parallel_walk(criterion); }); });
        EXPECT_TRUE(parallel == serial) << what << ", " << t << " threads: " << parallel.leaves.size() << " leaves, "
                                        << parallel.refused.value_or("accepted") << "; serial: " << serial.leaves.size()
                                        << " leaves, " << serial.refused.value_or("accepted");
    }
    return serial;
}

// About `dualhex mesh --preset fine`: a size of 1 % of the bounding-box diagonal.
SurfaceOctreeOptions fine(const AabbTree& tree) {
    SurfaceOctreeOptions o;
    o.max_depth = 12;
    o.surface_size = (kSanitized ? 0.02 : 0.01) * tree.bounds().diagonal().norm();
    o.curvature_angle = 40 * 3.14159265358979 / 180;
    o.curvature_levels = 1;
    return o;
}

TEST(GeometryOctreeThreads, BunnyIsTheSerialOctree) {
    const AabbTree tree(read_surface(shared_surface("gao_bunny_tri.off")));
    const SurfaceOctreeOptions o = fine(tree);
    expect_same_as_serial(tree, o, "bunny");
    // surface_octree itself (the walk plus the grid) at 1 and 2 threads.
    std::vector<Leaf> one, two;
    tbb::task_arena(1).execute([&] { one = surface_octree(tree, o).grid.leaves(); });
    tbb::task_arena(2).execute([&] { two = surface_octree(tree, o).grid.leaves(); });
    EXPECT_EQ(one, two);
    EXPECT_GT(one.size(), kSanitized ? 10'000u : 50'000u);
}

TEST(GeometryOctreeThreads, ThicknessAndDefaultsAreTheSerialOctree) {
    const AabbTree fandisk(read_surface(shared_surface("cgal_fandisk.off")));
    expect_same_as_serial(fandisk, SurfaceOctreeOptions{}, "fandisk, defaults");
    auto slab = unit_cube_surface();
    for (auto& p : slab.vertices) p.z() *= 0.01;
    SurfaceOctreeOptions o;
    o.max_depth = 9;
    expect_same_as_serial(AabbTree(slab), o, "thin slab");
}

// Near and past the budget: the parallel count gives up once the octree has more than
// max_leaves leaves; the serial walk then decides. At N - 1 (N: the octree's leaves) the
// serial walk may still accept (its count is the leaves before a split, + 8); at N / 2 it
// refuses. Both must come out the same at every thread count.
TEST(GeometryOctreeThreads, TheBudgetRefusesAsTheSerialWalkDoes) {
    const AabbTree fandisk(read_surface(shared_surface("cgal_fandisk.off")));
    SurfaceOctreeOptions o;
    const std::size_t n = surface_octree(fandisk, o).grid.size();
    std::vector<std::string> seen;
    for (std::size_t limit : {n, n - 1, n - 7, n / 2, std::size_t{9}}) {
        o.max_leaves = limit;
        const Outcome serial = expect_same_as_serial(fandisk, o, ("max_leaves " + std::to_string(limit)).c_str());
        seen.push_back(serial.refused.value_or("accepted"));
    }
    EXPECT_EQ(seen[0], "accepted");
    EXPECT_EQ(seen[1], "accepted");  // the parallel count gave up, the serial walk accepts
    EXPECT_NE(seen[3], "accepted");
    o.max_leaves = n / 2;
    EXPECT_THROW((void)surface_octree(fandisk, o), OctreeTooLarge);
}

// The comparison can fail: an outcome differing in order, or refused instead of accepted.
TEST(GeometryOctreeThreads, TheComparisonSeesOrderAndRefusal) {
    const AabbTree fandisk(read_surface(shared_surface("cgal_fandisk.off")));
    const SurfaceRefinement criterion(fandisk, SurfaceOctreeOptions{});
    const Outcome serial = outcome([&] { return detail::serial_walk(criterion); });
    Outcome swapped = serial;
    std::swap(swapped.leaves[3], swapped.leaves[4]);
    EXPECT_FALSE(swapped == serial);
    Outcome refused = serial;
    refused.refused = "surface octree: more than 9 leaves";
    EXPECT_FALSE(refused == serial);
}

}  // namespace
}  // namespace dualhex::geometry

// The parallel refinements (balance, pair_only, pair: a level-by-level closure over sorted
// arrays, grid/src/refinement.cpp) give the very grid of the serial ripple they replaced
// (tests/reference_refinement.hpp), leaf for leaf and in the same order, under oneTBB task
// arenas of 1, 2 and 4 threads: on random octrees, on the shared sphere grids refined
// further at random, and on the weakly balanced shared grids balanced strongly.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <functional>
#include <random>
#include <string>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/refinement.hpp"
#include "reference_refinement.hpp"
#include "test_grid_generators.hpp"
#include "sanitized.hpp"

namespace dualhex {
namespace {

constexpr int kThreads[] = {1, 2, 4};

// Under AddressSanitizer the shared grids are the d5 ones only.
using testing::kSanitized;

// Every refinement of `grid`, each run in arenas of 1, 2 and 4 threads, must equal the
// reference. Returns the first difference ("" if none).
std::string compare_all(const LeafGrid& grid) {
    static const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
    using Op = std::function<LeafGrid(const LeafGrid&)>;
    const std::pair<const char*, std::pair<Op, Op>> ops[] = {
        {"balance strong", {[](const LeafGrid& g) { return balance(g, Balance::Strong); },
                            [](const LeafGrid& g) { return testing::reference::balance(g, Balance::Strong); }}},
        {"balance weak", {[](const LeafGrid& g) { return balance(g, Balance::Weak); },
                          [](const LeafGrid& g) { return testing::reference::balance(g, Balance::Weak); }}},
        {"pair_only", {[](const LeafGrid& g) { return pair_only(g); },
                       [](const LeafGrid& g) { return testing::reference::pair_only(g); }}},
        {"pair strong", {[](const LeafGrid& g) { return pair(g, Balance::Strong); },
                         [](const LeafGrid& g) { return testing::reference::pair(g, Balance::Strong); }}},
        {"pair weak", {[](const LeafGrid& g) { return pair(g, Balance::Weak); },
                       [](const LeafGrid& g) { return testing::reference::pair(g, Balance::Weak); }}},
    };
    for (const auto& [name, op] : ops) {
        const LeafGrid expected = op.second(grid);
        for (int t : kThreads) {
            std::vector<Leaf> got;
            tbb::task_arena(t).execute([&] { got = op.first(grid).leaves(); });
            if (got != expected.leaves())
                return std::string(name) + " with " + std::to_string(t) + " threads: " + std::to_string(got.size()) +
                       " leaves against the reference's " + std::to_string(expected.size());
        }
    }
    return {};
}

RC_GTEST_PROP(GridRefinementThreads, RandomOctreesMatchTheSerialRipple, ()) {
    const LeafGrid grid = *testing::gen_octree(5);
    const std::string diff = compare_all(grid);
    RC_ASSERT(diff == std::string());
}

// A shared grid with `splits` random leaves split once more (no longer balanced or paired).
LeafGrid shared_refined(const std::string& name, int splits, unsigned seed) {
    const LeafGrid grid = read_leaf_file(std::string(DUALHEX_SHARED_DATA) + "/grids/" + name + ".leaves");
    std::mt19937 rng(seed);
    std::vector<char> split(grid.size(), 0);
    for (int s = 0; s < splits; ++s) split[rng() % grid.size()] = 1;
    std::vector<Leaf> leaves;
    for (std::size_t n = 0; n < grid.size(); ++n) {
        if (!split[n]) leaves.push_back(grid.leaf(n));
        else for (const Leaf& c : children(grid.leaf(n))) leaves.push_back(c);
    }
    return LeafGrid(std::move(leaves));
}

TEST(GridRefinementThreads, SharedGridsRefinedAtRandomMatchTheSerialRipple) {
    for (const char* name : {"sphere_strong_d5", "sphere_weak_d5", "sphere_weak_d6"}) {
        if (kSanitized && std::string(name) == "sphere_weak_d6") continue;
        const LeafGrid grid = shared_refined(name, 200, 7);
        EXPECT_EQ(compare_all(grid), "") << name;
    }
}

TEST(GridRefinementThreads, WeakSharedGridBalancedStronglyMatchesTheSerialRipple) {
    const LeafGrid weak = read_leaf_file(std::string(DUALHEX_SHARED_DATA) + "/grids/" +
                                         (kSanitized ? "sphere_weak_d5" : "sphere_weak_d6") + ".leaves");
    const LeafGrid expected = testing::reference::pair(weak, Balance::Strong);
    ASSERT_GT(expected.size(), weak.size());  // there is work to do
    for (int t : kThreads) {
        std::vector<Leaf> got;
        tbb::task_arena(t).execute([&] { got = pair(weak, Balance::Strong).leaves(); });
        EXPECT_EQ(got, expected.leaves()) << t << " threads";
    }
}

// The comparison can fail: a grid that differs from the reference in one leaf's order is
// caught, as is one that differs in one split.
TEST(GridRefinementThreads, TheComparisonSeesOrderAndContent) {
    const LeafGrid grid = shared_refined("sphere_weak_d5", 50, 3);
    std::vector<Leaf> expected = testing::reference::pair(grid, Balance::Strong).leaves();
    const std::vector<Leaf> got = pair(grid, Balance::Strong).leaves();
    ASSERT_EQ(got, expected);
    std::swap(expected[10], expected[11]);
    EXPECT_NE(got, expected);
    const LeafGrid finer = pair(shared_refined("sphere_weak_d5", 51, 3), Balance::Strong);
    EXPECT_NE(finer.leaves(), got);
}

}  // namespace
}  // namespace dualhex

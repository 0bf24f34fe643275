// The parallel refinements (balance, pair_only, pair: a level-by-level closure over sorted
// arrays, grid/src/refinement.cpp) give the very grid of the serial ripple they replaced
// (tests/reference_refinement.hpp), leaf for leaf and in the same order, under oneTBB task
// arenas of 1, 2 and 4 threads: on random octrees, on the shared sphere grids refined
// further at random, and on the weakly balanced shared grids balanced strongly. LeafGrid's
// hash index (hashed in parallel, inserted serially) holds what a plain serial build of the
// map holds, slot for slot (the iteration order of interior_nodes), at 1, 2 and 4 threads,
// and names the same bad leaf in its errors.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <functional>
#include <numeric>
#include <random>
#include <string>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "dualhex/grid/cell_map.hpp"
#include "dualhex/grid/input_error.hpp"
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

// The oracle of LeafGrid's index: the map built by plain inserts in the serial order
// (leaves, then each leaf's ancestors up to the first known one); its interior nodes in
// slot order with the leaf each names.
std::vector<std::pair<Leaf, std::int32_t>> serial_index_interior(const std::vector<Leaf>& leaves) {
    CellMap<std::int32_t> map(2 * leaves.size());
    for (std::size_t n = 0; n < leaves.size(); ++n) map.insert(leaves[n], static_cast<std::int32_t>(n));
    for (std::size_t n = 0; n < leaves.size(); ++n)
        for (int level = leaves[n].level - 1; level >= 0; --level)
            if (!map.insert(ancestor(leaves[n], level), -1 - static_cast<std::int32_t>(n)).second) break;
    std::vector<std::pair<Leaf, std::int32_t>> out;
    map.for_each([&](const Leaf& cell, std::int32_t v) {
        if (v < 0) out.emplace_back(cell, -1 - v);
    });
    return out;
}

// "" if the grid's index equals the oracle's (order of interior nodes, the leaf each
// names, every leaf found at its index); else the first difference.
std::string index_difference(const LeafGrid& grid, const std::vector<std::pair<Leaf, std::int32_t>>& expected) {
    const std::vector<Leaf> interior = grid.interior_nodes();
    if (interior.size() != expected.size())
        return std::to_string(interior.size()) + " interior nodes, the oracle " + std::to_string(expected.size());
    for (std::size_t i = 0; i < interior.size(); ++i) {
        if (!(interior[i] == expected[i].first)) return "interior node " + std::to_string(i) + " differs";
        if (grid.leaf_within(interior[i]) != static_cast<std::size_t>(expected[i].second))
            return "interior node " + std::to_string(i) + " names another leaf";
    }
    for (std::size_t n = 0; n < grid.size(); ++n)
        if (grid.find(grid.leaf(n)) != n) return "leaf " + std::to_string(n) + " not found at its index";
    return {};
}

TEST(GridIndexThreads, TheIndexIsTheSerialOneAtEveryThreadCount) {
    static const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
    for (const char* name : {"sphere_strong_d5", "sphere_weak_d6"}) {
        if (kSanitized && std::string(name) == "sphere_weak_d6") continue;
        const LeafGrid refined = shared_refined(name, 300, 11);
        const auto expected = serial_index_interior(refined.leaves());
        ASSERT_GT(expected.size(), 1000u);
        for (int t : kThreads) {
            std::string diff;
            tbb::task_arena(t).execute([&] { diff = index_difference(LeafGrid(refined.leaves()), expected); });
            EXPECT_EQ(diff, "") << name << ", " << t << " threads";
        }
    }
}

// The index comparison can fail: the leaves in another order give another slot layout
// (and other leaves named), which it sees.
TEST(GridIndexThreads, TheIndexComparisonSeesAnotherOrder) {
    const LeafGrid grid = shared_refined("sphere_strong_d5", 100, 5);
    std::vector<Leaf> reversed(grid.leaves().rbegin(), grid.leaves().rend());
    EXPECT_EQ(index_difference(grid, serial_index_interior(grid.leaves())), "");
    EXPECT_NE(index_difference(LeafGrid(reversed), serial_index_interior(grid.leaves())), "");
}

// Bad leaves are named as the serial build names them (the first bad one in input order)
// at every thread count: a duplicate before an invalid leaf, an overlap, an invalid leaf.
TEST(GridIndexThreads, ErrorsNameTheSameLeafAtEveryThreadCount) {
    static const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
    const LeafGrid base = shared_refined("sphere_strong_d5", 10, 2);
    std::vector<Leaf> duplicate = base.leaves(), overlap = base.leaves(), invalid = base.leaves();
    duplicate.insert(duplicate.begin() + 5000, duplicate[17]);
    duplicate.push_back(Leaf{3, 9, 0, 0});  // invalid, but after the duplicate
    overlap.push_back(ancestor(overlap[4000], overlap[4000].level - 1));
    invalid[6000] = Leaf{2, 0, 4, 0};
    const std::pair<const std::vector<Leaf>*, const char*> cases[] = {
        {&duplicate, "grid.leaves:5001: duplicate leaf"}, {&overlap, "overlap"}, {&invalid, "grid.leaves:6001: invalid"}};
    for (const auto& [leaves, what] : cases) {
        std::vector<int> lines(leaves->size());
        std::iota(lines.begin(), lines.end(), 1);
        std::vector<std::string> messages;
        for (int t : kThreads)
            tbb::task_arena(t).execute([&] {
                try {
                    (void)LeafGrid(*leaves, "grid.leaves", lines);
                    messages.emplace_back("no error");
                } catch (const InputError& e) {
                    messages.emplace_back(e.what());
                }
            });
        EXPECT_NE(messages[0].find(what), std::string::npos) << messages[0];  // the first bad leaf, its line
        EXPECT_EQ(messages[1], messages[0]);
        EXPECT_EQ(messages[2], messages[0]);
    }
}

}  // namespace
}  // namespace dualhex

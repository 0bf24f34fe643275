// Weakly balanced grids: the configuration space, the weak rule over all of it, and a
// mutation (the strong rule, which ignores two-level jumps) that must fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/checkers/weak_exhaustive.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/weak_rule.hpp"

namespace dualhex {
namespace {

const ElementLibrary& library() {
    static const ElementLibrary lib = ElementLibrary::load_default();
    return lib;
}

TEST(WeakConfigurations, CountsAndClasses) {
    const auto all = weak_configurations();
    EXPECT_EQ(all.size(), 487u);
    std::set<LevelAssignment> classes, three;
    std::size_t three_level = 0;
    for (const auto& lv : all) {
        classes.insert(canonical(lv));
        if (*std::max_element(lv.begin(), lv.end()) == 2) {
            ++three_level;
            three.insert(canonical(lv));
        }
        // canonical() is a class invariant: idempotent, never larger than the input
        EXPECT_EQ(canonical(canonical(lv)), canonical(lv));
        EXPECT_LE(canonical(lv), lv);
    }
    EXPECT_EQ(three_level, 232u);
    EXPECT_EQ(classes.size(), 35u);  // 21 two-level (the strong case's 22 minus all-fine) + 14
    EXPECT_EQ(three.size(), 14u);
}

TEST(WeakRule, EveryWeakConfigurationPasses) {
    const WeakRule rule;
    const auto r = run_weak_exhaustive(rule, library());
    EXPECT_EQ(r.configurations, 487);
    EXPECT_EQ(r.passed, 487) << (r.failures.empty() ? "" : r.failures.front());
    EXPECT_EQ(r.periodic_passed, 487);
    EXPECT_EQ(r.window_passed, 487);
    EXPECT_EQ(r.max_dual_edge_valence, 7);
    for (const char* name : {"E-MR", "VC1-MR", "VC2-MR", "VC3-MR"}) EXPECT_GT(r.elements.count(name), 0u) << name;
}

// An open concave edge whose diagonal octant is two levels finer: octant levels by (y, z).
int open_concave_edge(int, int y, int z) {
    static const int level[2][2] = {{0, 1}, {1, 2}};
    return level[y & 1][z & 1];
}

TEST(WeakRule, PlacesEmrOnAnOpenConcaveEdge) {
    const auto built = build_periodic_levels(open_concave_edge, 2, WeakRule(), library());
    std::size_t emr = 0;
    for (const auto& leaf : built.coarse_leaves)
        if (leaf.placement && leaf.placement->element == "E-MR") ++emr;
    EXPECT_EQ(emr, 16u);
    EXPECT_TRUE(check_periodic_levels(open_concave_edge, 2, WeakRule(), library()).ok());
}

TEST(WeakRule, TheStrongRuleAloneFailsThere) {
    // Without the truncation the finer transition's bend has nowhere to go: holes and
    // wrong valences along the edge.
    const auto r = check_periodic_levels(open_concave_edge, 2, StrongRule(), library());
    EXPECT_FALSE(r.ok());
    EXPECT_GT(r.open_faces + r.validation.violations.size(), 0u);
}

}  // namespace
}  // namespace dualhex

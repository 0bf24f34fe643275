// The weak rule's reduction facts (checkers/compositional_weak.hpp): it sees only its
// visible context, the weak lemma, its whole visible domain, wrong rules, and the grid
// with the largest level spread at a point installed and checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "dualhex/checkers/compositional_weak.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/install/install.hpp"
#include "dualhex/install/verify_installation.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "test_wrong_rules.hpp"

namespace dualhex {
namespace {

const ElementLibrary& library() {
    static const ElementLibrary lib = ElementLibrary::load_default();
    return lib;
}

struct Seen {
    bool threw = false;
    std::optional<Placement> placement;
    bool operator==(const Seen&) const = default;
};

Seen place(const TransitionRule& rule, const LeafContext& ctx) {
    try {
        return {false, rule.place(ctx)};
    } catch (const UnknownPatternError&) {
        return {true, std::nullopt};
    }
}

TEST(WeakReach, TheRuleSeesOnlyItsVisibleContext) {
    const WeakRule rule;
    EXPECT_EQ(rule.reach(), strong_reach());
    std::mt19937_64 random(20261202);
    int mr = 0;
    for (int n = 0; n < 20000; ++n) {
        LeafContext full;
        full.neighbourhood = random() & ~(std::uint64_t{1} << LeafContext::neighbourhood_bit(0, 0, 0));
        full.edge_two_finer = static_cast<std::uint8_t>(random() & 7U);
        const LeafContext seen = weak_visible(full);
        EXPECT_EQ(seen.neighbourhood, full.neighbourhood & strong_reach());
        EXPECT_EQ(seen.edge_two_finer & ~full.edge_two_finer, 0);
        const Seen a = place(rule, full), b = place(rule, seen);
        ASSERT_EQ(a, b) << full.describe();
        if (a.placement && a.placement->element.find("-MR") != std::string::npos) ++mr;
    }
    EXPECT_GT(mr, 100);  // the edge bits are read: the MR elements occur
}

TEST(WeakReach, EdgeBitsCountOnlyAtConcaveEdges) {
    LeafContext ctx;  // interfaces x and y: the z-edge is concave, the x- and y-edges are not
    ctx.set_fine(-1, 0, 0);
    ctx.set_fine(0, -1, 0);
    ctx.set_fine(-1, -1, 0);
    EXPECT_EQ(weak_visible(ctx).edge_two_finer, 0);
    ctx.edge_two_finer = 0b011;
    EXPECT_EQ(weak_visible(ctx).edge_two_finer, 0);  // not concave: masked off
    EXPECT_EQ(WeakRule().place(ctx)->element, "E");
    ctx.edge_two_finer = 0b100;
    EXPECT_EQ(weak_visible(ctx).edge_two_finer, 0b100);
    EXPECT_EQ(WeakRule().place(ctx)->element, "E-MR");
}

TEST(WeakLemmas, HoldForTheWeakRule) {
    const WeakLemmaResult r = check_weak_lemmas(WeakRule());
    EXPECT_EQ(r.reach_octants, 10);
    EXPECT_EQ(r.lemma_contexts, 64);  // 3 far-face bits and 3 edge bits free
    EXPECT_TRUE(r.lemma_holds());
    EXPECT_EQ(r.visible_contexts, 4096);  // 9 octant bits (own coarse) x 3 edge bits
    EXPECT_EQ(r.placed + r.plain + r.refused, r.visible_contexts);
    EXPECT_EQ(r.refused, 0);
    EXPECT_EQ(r.plain, r.lemma_contexts);  // plain exactly when nothing at P is fine
    EXPECT_EQ(r.mr_contexts, 640);         // pinned: a change of the rule shows here
    EXPECT_EQ(r.nonconcave_ignored, r.nonconcave_contexts);
    EXPECT_GT(r.nonconcave_contexts, 0);
    EXPECT_GT(r.mr_contexts, 0);
    for (const char* name : {"E-MR", "VS-MR", "VC1-MR", "VC2-MR", "VC3-MR"}) EXPECT_GT(r.elements.count(name), 0u) << name;
    EXPECT_TRUE(r.all_passed());
}

// A weak rule that reads an edge bit where the edge is not concave, one that places a
// truncated element where there is no two-levels-finer neighbour, one with an MR element
// missing: each is caught by the facts above.
class WeakWrong : public TransitionRule {
public:
    enum Mode { ReadsFlatEdge, MrWithoutFiner, MissingMr };
    explicit WeakWrong(Mode m) : mode_(m) {}
    std::optional<Placement> place(const LeafContext& ctx) const override {
        if (mode_ == ReadsFlatEdge && ctx.edge_two_finer && ctx.fine(-1, 0, 0) && !ctx.fine(0, -1, 0))
            return Placement{"C1", {}};
        auto p = WeakRule().place(ctx);
        if (mode_ == MrWithoutFiner && p && p->element == "E" && ctx.fine(1, 0, 0)) p->element = "E-MR";
        if (mode_ == MissingMr && p && p->element == "VC2-MR") throw UnknownPatternError("no VC2-MR");
        return p;
    }
    std::uint64_t reach() const override { return strong_reach(); }

private:
    Mode mode_;
};

TEST(WeakLemmas, WrongWeakRulesAreCaught) {
    EXPECT_FALSE(check_weak_lemmas(WeakWrong(WeakWrong::ReadsFlatEdge)).all_passed());
    EXPECT_FALSE(check_weak_lemmas(WeakWrong(WeakWrong::MissingMr)).all_passed());
    // An MR element without an edge bit is not a lemma violation but changes the element
    // census: the enumeration's own counts (E-MR contexts) show it.
    const auto right = check_weak_lemmas(WeakRule()), wrong = check_weak_lemmas(WeakWrong(WeakWrong::MrWithoutFiner));
    EXPECT_NE(right.elements.at("E-MR"), wrong.elements.at("E-MR"));
}

// W3 of proofs/README.md: at a point, weak balance allows leaves of four consecutive levels.
// Over the 8 octant cubes around a point, the level assignments 0..3 with face-adjacent
// octants within one level are the 487 weak configurations and 8 more, the four-level ones:
// one octant 0, the opposite one 3 (level = 3 - distance in the cube graph).
TEST(WeakSpread, TheFourLevelOctantAssignments) {
    int all = 0, four = 0;
    for (int code = 0; code < 1 << 16; ++code) {
        std::array<int, 8> lv{};
        for (int b = 0; b < 8; ++b) lv[static_cast<std::size_t>(b)] = (code >> (2 * b)) & 3;
        bool ok = *std::min_element(lv.begin(), lv.end()) == 0;
        for (int b = 0; b < 8 && ok; ++b)
            for (int a = 0; a < 3; ++a) ok = ok && std::abs(lv[static_cast<std::size_t>(b)] - lv[static_cast<std::size_t>(b ^ (1 << a))]) <= 1;
        if (!ok) continue;
        ++all;
        if (*std::max_element(lv.begin(), lv.end()) < 3) continue;
        ++four;
        const int c = static_cast<int>(std::find(lv.begin(), lv.end(), 3) - lv.begin());
        for (int b = 0; b < 8; ++b) EXPECT_EQ(lv[static_cast<std::size_t>(b)], 3 - std::popcount(static_cast<unsigned>(b ^ c)));
    }
    EXPECT_EQ(all, 495);
    EXPECT_EQ(four, 8);
}

// The least paired weakly balanced refinement reaching level m+3 at the corner of a level-m
// leaf keeps that leaf: the spread 3 is attained, at each of the 8 corners.
TEST(WeakSpread, FourLevelsMeetAtAPoint) {
    const int m = 2;
    for (int corner = 0; corner < 8; ++corner) {
        const LeafGrid grid = spread_three_grid(m, corner);
        ASSERT_TRUE(is_paired(grid).ok);
        ASSERT_TRUE(is_weakly_balanced(grid).ok);
        EXPECT_FALSE(is_strongly_balanced(grid).ok);
        EXPECT_EQ(levels_at(grid, {2, 2, 2}, m), (std::vector<int>{m, m + 1, m + 1, m + 1, m + 2, m + 2, m + 2, m + 3}))
            << corner;
    }
}

// Tested, not proved: the weak rule installs those grids (elements on three levels at the
// point: VC3-MR, E-MR, F) to valid complexes under both root policies.
TEST(WeakSpread, TheWeakRuleInstallsIt) {
    for (int corner = 0; corner < 8; ++corner)
        for (OutsideRoot policy : {OutsideRoot::Coarse, OutsideRoot::Mirror}) {
            InstallOptions options;
            options.outside_root = policy;
            const InstallResult installed = install(spread_three_grid(2, corner), WeakRule(), library(), options);
            const auto used = installed.elements_used();
            for (const char* name : {"VC3-MR", "E-MR", "F"}) EXPECT_GT(used.count(name), 0u) << name << ' ' << corner;
            const InstallVerification v = verify_installation(installed);
            EXPECT_TRUE(v.ok()) << corner << ' ' << v.summary();
            EXPECT_GT(v.interior_vertices, 900u);
        }
}

TEST(WeakSpread, WrongMrElementsAreCaughtThere) {
    const LeafGrid grid = spread_three_grid(2);
    const InstallVerification v = verify_installation(install(grid, test::WeakMutant(false), library()));
    EXPECT_FALSE(v.ok());
    EXPECT_THROW((void)install(grid, test::WeakMutant(true), library()), InstallError);
}

TEST(WeakWindows, WhatABoxWindowWouldRead) {
    const auto reads = weak_window_reads();
    ASSERT_EQ(reads.size(), 8u);
    for (const auto& r : reads) {
        const int odd = r.parity[0] + r.parity[1] + r.parity[2];
        EXPECT_EQ(r.octants, odd == 0 ? 32 : odd == 3 ? 19 : 20) << odd;  // the strong case's R(t)
        EXPECT_EQ(r.application_points, 27);
        EXPECT_GT(r.shared_cells, r.octants);
        std::printf("g=(%d,%d,%d): %d octants, %d level-m cells read (%d shared), %d application points\n", r.parity[0],
                    r.parity[1], r.parity[2], r.octants, r.cells, r.shared_cells, r.application_points);
    }
}

}  // namespace
}  // namespace dualhex

// The compositional argument (checkers/compositional.hpp): the strong rule passes every
// window of every parity type, the reduction lemma holds, and wrong rules are caught.
#include <gtest/gtest.h>

#include <random>

#include "dualhex/checkers/compositional.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "test_wrong_rules.hpp"

namespace dualhex {
namespace {

const ElementLibrary& library() {
    static const ElementLibrary lib = ElementLibrary::load_default();
    return lib;
}

int popcount(std::uint64_t x) {
    int n = 0;
    for (; x; x &= x - 1) ++n;
    return n;
}

TEST(StrongReach, TenOctantsAndTheRuleIgnoresTheRest) {
    EXPECT_EQ(popcount(strong_reach()), 10);
    EXPECT_FALSE((strong_reach() >> LeafContext::neighbourhood_bit(-1, -1, -1)) & 1U);  // not the corner diagonal
    const StrongRule rule;
    std::mt19937_64 random(20261122);
    for (int n = 0; n < 20000; ++n) {
        LeafContext full;
        full.neighbourhood = random() & ~(std::uint64_t{1} << LeafContext::neighbourhood_bit(0, 0, 0));
        full.edge_two_finer = static_cast<std::uint8_t>(random() & 7U);
        LeafContext seen = full;
        seen.neighbourhood &= strong_reach();
        seen.edge_two_finer = 0;
        std::optional<Placement> a, b;
        bool threw_a = false, threw_b = false;
        try { a = rule.place(full); } catch (const UnknownPatternError&) { threw_a = true; }
        try { b = rule.place(seen); } catch (const UnknownPatternError&) { threw_b = true; }
        ASSERT_EQ(threw_a, threw_b) << full.describe();
        ASSERT_EQ(a, b) << full.describe();
    }
}

TEST(Compositional, StrongRulePassesEveryWindowOfEveryType) {
    const CompositionalResult r = run_compositional(StrongRule(), library());
    for (const auto& f : r.failures) ADD_FAILURE() << f;
    EXPECT_EQ(r.reach_octants, 10);
    EXPECT_EQ(r.lemma_contexts, 8);  // the own octant coarse, the 6 read at P coarse: 3 far bits free
    EXPECT_TRUE(r.lemma_holds());
    ASSERT_EQ(r.types.size(), 8u);
    // Read octants per parity type (number of odd coordinates of g: 0, 1, 2, 3).
    for (const auto& t : r.types) {
        const int odd = t.parity[0] + t.parity[1] + t.parity[2];
        EXPECT_EQ(t.read_octants, odd == 0 ? 32 : odd == 3 ? 19 : 20) << odd;
        EXPECT_EQ(t.passed, t.windows);
        EXPECT_GT(t.checked_vertices, t.windows);
    }
    EXPECT_TRUE(r.all_passed());
    EXPECT_EQ(r.windows, 36635u);  // pinned: a change of the rule or the enumeration shows here
}


TEST(Compositional, WrongRulesAreCaught) {
    CompositionalOptions stop_early;
    stop_early.stop_after_failures = 1;
    for (test::WrongChoiceMode mode : {test::WrongChoiceMode::MisorientedE, test::WrongChoiceMode::MissingVC}) {
        const CompositionalResult r = run_compositional(test::WrongChoice(mode), library(), stop_early);
        EXPECT_FALSE(r.all_passed()) << static_cast<int>(mode);
        EXPECT_GE(r.failed, 1u) << static_cast<int>(mode);
        EXPECT_FALSE(r.failures.empty()) << static_cast<int>(mode);
    }
    const CompositionalResult lemma =
        run_compositional(test::WrongChoice(test::WrongChoiceMode::AgainstLemma), library(), stop_early);
    EXPECT_FALSE(lemma.lemma_holds());
    EXPECT_FALSE(lemma.all_passed());
}

}  // namespace
}  // namespace dualhex

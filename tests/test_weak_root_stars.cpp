// W13 of proofs/README.md (checkers/compositional_weak_root_stars.hpp): the weak stars of
// vertices on the root surface under Mirror and Coarse, checked with B1-B5; wrong rules fail.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <string>

#include "dualhex/checkers/compositional_weak_root_stars.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "test_wrong_rules.hpp"

namespace dualhex {
namespace {

const ElementLibrary& library() {
    static const ElementLibrary lib = ElementLibrary::load_default();
    return lib;
}

const WeakStarInfluence& weak_influence() {
    static const WeakStarInfluence r = weak_star_influence(WeakRule(), library());
    return r;
}

void print(const WeakRootStarCheck& r) {
    std::printf("%s %s: types %ld/%ld/%ld pairs %ld/%ld/%ld stars %ld/%ld/%ld empty %ld/%ld/%ld passed %ld/%ld/%ld failed %ld/%ld/%ld nodes %ld max_free %d\n",
                r.rule.c_str(), r.policy.c_str(), r.types[0], r.types[1], r.types[2], r.pairs[0], r.pairs[1], r.pairs[2],
                r.stars[0], r.stars[1], r.stars[2], r.empty[0], r.empty[1], r.empty[2], r.passed[0], r.passed[1], r.passed[2],
                r.failed[0], r.failed[1], r.failed[2], r.search_nodes, r.max_free);
    for (const auto& f : r.failures) std::printf("  %s\n", f.c_str());
}

std::string key(const WeakRootStar& s) {
    std::ostringstream os;
    os << s.sides[0] << s.sides[1] << s.sides[2] << ' ' << s.parity[0] << s.parity[1] << s.parity[2] << ' ' << s.v;
    for (std::size_t n = 0; n < s.leaves.size(); ++n)
        os << " [" << s.leaves[n].first << ' ' << s.leaves[n].second[0] << ',' << s.leaves[n].second[1] << ','
           << s.leaves[n].second[2] << ':' << s.pieces[n] << ']';
    return os.str();
}

// Both policies, every type: every star passes B1-B5, with the pinned counts (face, edge,
// corner vertices); the two policies give the same stars (W13: a leaf at v has its
// application point on the plane, and what it reads beyond it does not change its cells at
// v under either policy, computed here).
TEST(WeakRootStars, EveryStarOnTheRootSurfaceIsValid) {
    std::map<BoundaryPolicy, std::set<std::string>> seen;
    std::mutex mutex;
    for (const BoundaryPolicy policy : {BoundaryPolicy::Mirror, BoundaryPolicy::Coarse}) {
        WeakRootStarOptions o;
        o.stars = [&](const WeakRootStar& s) {
            const std::lock_guard lock(mutex);
            seen[policy].insert(key(s));
        };
        const WeakRootStarCheck r = run_weak_root_stars(WeakRule(), library(), weak_influence(), policy, o);
        print(r);
        EXPECT_TRUE(r.all_passed()) << (r.failures.empty() ? "" : r.failures.front());
        EXPECT_EQ(r.types, (std::array<long, 3>{24, 24, 8}));
        EXPECT_EQ(r.pairs, (std::array<long, 3>{4764, 432, 8}));
        EXPECT_EQ(r.stars, (std::array<long, 3>{3372, 144, 8}));
        EXPECT_EQ(r.empty, (std::array<long, 3>{4512, 384, 0}));
        EXPECT_EQ(r.passed, r.stars);
        EXPECT_EQ(r.total(r.failed), 0);
    }
    EXPECT_EQ(seen[BoundaryPolicy::Mirror].size(), 8420u);  // 3,524 stars and 4,896 empty tuples
    EXPECT_EQ(seen[BoundaryPolicy::Mirror], seen[BoundaryPolicy::Coarse]);
}

// E-MR mis-oriented fails under both policies; VC3-MR missing passes with the weak rule's
// stars (a star holding one would fail: the rule throws; none does, since a leaf at v has its
// application point on the root plane and the octant cube across it is not fine under either
// policy, so never three fine faces there); a policy whose readers disagree
// about an outside cell (fine for leaves of even cell index y, coarse for the others) fails,
// while reading every outside cell fine, a policy that is a function of the cell, passes.
TEST(WeakRootStars, WrongRulesAndPoliciesAreCaught) {
    const test::WeakMutant misoriented(false), missing(true);
    const WeakStarInfluence misoriented_influence = weak_star_influence(misoriented, library());
    const WeakStarInfluence missing_influence = weak_star_influence(missing, library());
    for (const BoundaryPolicy policy : {BoundaryPolicy::Mirror, BoundaryPolicy::Coarse}) {
        const WeakRootStarCheck wrong = run_weak_root_stars(misoriented, library(), misoriented_influence, policy);
        print(wrong);
        EXPECT_EQ(wrong.failed, (std::array<long, 3>{708, 0, 0}));
        EXPECT_FALSE(wrong.all_passed());
        const WeakRootStarCheck absent = run_weak_root_stars(missing, library(), missing_influence, policy);
        EXPECT_TRUE(absent.all_passed());
        EXPECT_EQ(absent.stars, (std::array<long, 3>{3372, 144, 8}));
    }
    WeakRootStarOptions disagree;
    disagree.outside_fine_for = [](int, const std::array<std::int64_t, 3>& c) { return c[1] % 2 == 0; };
    const WeakRootStarCheck broken = run_weak_root_stars(WeakRule(), library(), weak_influence(), BoundaryPolicy::Coarse, disagree);
    print(broken);
    EXPECT_FALSE(broken.all_passed());
    EXPECT_EQ(broken.failed, (std::array<long, 3>{1484, 44, 0}));
    WeakRootStarOptions fine;
    fine.outside_fine_for = [](int, const std::array<std::int64_t, 3>&) { return true; };
    const WeakRootStarCheck all_fine = run_weak_root_stars(WeakRule(), library(), weak_influence(), BoundaryPolicy::Coarse, fine);
    EXPECT_TRUE(all_fine.all_passed());
    EXPECT_EQ(all_fine.stars, (std::array<long, 3>{3924, 288, 8}));
}

}  // namespace
}  // namespace dualhex

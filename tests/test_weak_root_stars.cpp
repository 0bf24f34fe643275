// W13 of proofs/README.md (checkers/compositional_weak_root_stars.hpp): the weak stars of
// vertices on the root surface under Mirror and Coarse, checked with B1-B5; wrong rules fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <span>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <string>

#include "dualhex/checkers/compositional_weak_root_stars.hpp"
#include "dualhex/grid/refinement.hpp"
#include "dualhex/install.hpp"
#include "dualhex/topology/incidence.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "test_root_corner.hpp"
#include "test_weak_star_fixture.hpp"
#include "test_wrong_rules.hpp"

namespace dualhex {
namespace {

using test::library;
using test::weak_influence;

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

// Not every policy that is a function of the outside cell will do (AnyOutside: each outside
// cell a free status, no implication into or out of it; proofs/README.md W13 (g)): its stars
// contain those of Coarse (every outside cell 0) and of reading every outside cell fine
// (every one 1), which pass, but two inside leaves can then read two outside cells of
// different values and disagree across their common face: stars fail (pinned). So W13's
// result is for Coarse and Mirror, as stated, not for any policy.
TEST(WeakRootStars, AFreeOutsideCellBreaksTheWeakRule) {
    std::mutex mutex;
    const auto star_set = [&](BoundaryPolicy policy, const WeakRootStarOptions& base, WeakRootStarCheck& r) {
        std::set<std::string> out;
        WeakRootStarOptions o = base;
        o.stars = [&](const WeakRootStar& s) {
            const std::lock_guard lock(mutex);
            out.insert(key(s));
        };
        r = run_weak_root_stars(WeakRule(), library(), weak_influence(), policy, o);
        return out;
    };
    WeakRootStarCheck any, coarse, fine;
    WeakRootStarOptions all_fine;
    all_fine.outside_fine_for = [](int, const std::array<std::int64_t, 3>&) { return true; };
    const auto any_set = star_set(BoundaryPolicy::AnyOutside, {}, any);
    const auto coarse_set = star_set(BoundaryPolicy::Coarse, {}, coarse);
    const auto fine_set = star_set(BoundaryPolicy::Coarse, all_fine, fine);
    print(any);
    EXPECT_EQ(any.pairs, coarse.pairs);
    EXPECT_TRUE(std::includes(any_set.begin(), any_set.end(), coarse_set.begin(), coarse_set.end()));
    EXPECT_TRUE(std::includes(any_set.begin(), any_set.end(), fine_set.begin(), fine_set.end()));
    EXPECT_TRUE(coarse.all_passed());
    EXPECT_TRUE(fine.all_passed());
    EXPECT_EQ(any.stars, (std::array<long, 3>{48966, 7668, 320}));
    EXPECT_EQ(any.failed, (std::array<long, 3>{21552, 3360, 0}));
    EXPECT_FALSE(any.all_passed());
}

// The model against real installations. A star's geometry: its root sides and its cells at
// v (each as its outward loops, each loop from its smallest point), v at the origin, in the
// enumeration's units (a level-m cell is 8U); empty if a point is off that lattice.
std::string geometry(const RootSides& sides, const CellComplex& cx, std::span<const CellHandle> cells, const LatticePoint& v,
                     std::int64_t num, std::int64_t den) {
    std::vector<std::vector<std::vector<LatticePoint>>> out;
    for (CellHandle c : cells) {
        auto& cell = out.emplace_back();
        for (HalfFaceHandle h : cx.cell_halffaces(c)) {
            std::vector<LatticePoint> loop;
            for (VertexHandle w : cx.halfface_vertices(h)) {
                LatticePoint p = cx.position(w) - v;
                for (int a = 0; a < 3; ++a) {
                    if (p[a] * num % den != 0) return {};
                    p[a] = p[a] * num / den;
                }
                loop.push_back(p);
            }
            std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
            cell.push_back(std::move(loop));
        }
        std::sort(cell.begin(), cell.end());
    }
    std::sort(out.begin(), out.end());
    std::ostringstream os;
    os << sides[0] << ',' << sides[1] << ',' << sides[2];
    for (const auto& cell : out) {
        os << " {";
        for (const auto& loop : cell) {
            os << '(';
            for (const LatticePoint& p : loop) os << p << ' ';
            os << ')';
        }
        os << '}';
    }
    return os.str();
}

// Random refinement (each leaf split with probability 0.3 down to `depth`), paired, weakly
// balanced.
LeafGrid random_weak_grid(std::mt19937& random, int depth) {
    std::vector<Leaf> leaves, todo{Leaf{}};
    while (!todo.empty()) {
        const Leaf l = todo.back();
        todo.pop_back();
        if (l.level == 0 || (l.level < depth && std::bernoulli_distribution(0.3)(random))) {
            for (const Leaf& c : children(l)) todo.push_back(c);
        } else {
            leaves.push_back(l);
        }
    }
    return pair(LeafGrid(std::move(leaves)), Balance::Weak);
}

struct RealStars {
    long vertices = 0, found = 0, missing = 0, boundary_failures = 0;
    std::set<std::string> distinct;  // the real stars found
    std::string first_missing;
};

// Every root-surface vertex of random weakly balanced paired grids installed with `policy`:
// its star's geometry among `enumerated`, and check_boundary_vertices at every root corner.
RealStars real_surface_stars(OutsideRoot policy, const std::set<std::string>& enumerated, std::int64_t eight_u) {
    RealStars out;
    std::mt19937 random(20261204);
    for (int g = 0; g < 4; ++g) {
        const LeafGrid grid = random_weak_grid(random, 4 + g % 2);
        const InstallResult r = install(grid, WeakRule(), library(), {.outside_root = policy, .balance = Balance::Weak});
        EXPECT_TRUE(verify_installation(r).ok());
        const std::int64_t n = r.unit << r.max_level;
        const Incidence inc(r.complex);
        std::vector<int> level_of_cell(r.complex.n_cells());
        for (std::size_t leaf = 0; leaf < grid.size(); ++leaf)
            for (std::uint32_t c = r.leaf_cells[leaf]; c < r.leaf_cells[leaf + 1]; ++c) level_of_cell[c] = grid.leaf(leaf).level;
        for (std::size_t i = 0; i < r.complex.n_vertices(); ++i) {
            const VertexHandle v(i);
            const LatticePoint& p = r.complex.position(v);
            RootSides sides{};
            for (int a = 0; a < 3; ++a) sides[static_cast<std::size_t>(a)] = p[a] == 0 ? 1 : p[a] == n ? -1 : 0;
            if (sides == RootSides{}) continue;
            ++out.vertices;
            int m = 99;
            for (CellHandle c : inc.vertex_cells(v)) m = std::min(m, level_of_cell[c.index()]);
            const std::string key = geometry(sides, r.complex, inc.vertex_cells(v), p, eight_u, r.unit << (r.max_level - m));
            if (enumerated.count(key)) ++out.found, out.distinct.insert(key);
            else if (out.missing++ == 0) out.first_missing = key;
        }
        for (int corner = 0; corner < 8; ++corner)  // B1-B5 on the whole installation
            out.boundary_failures += static_cast<long>(
                check_boundary_vertices(test::root_corner_at_origin(r.complex, n, corner), n, {1, 1, 1}).failures.size());
    }
    return out;
}

std::set<std::string> enumerated_geometries(BoundaryPolicy policy, unsigned planes) {
    std::set<std::string> out;
    std::mutex mutex;
    WeakRootStarOptions o;
    o.planes = planes;
    o.stars = [&](const WeakRootStar& s) {
        if (!s.complex) return;
        std::vector<CellHandle> cells;
        for (std::size_t c = 0; c < s.complex->n_cells(); ++c) cells.push_back(CellHandle(c));
        const std::string key = geometry(s.sides, *s.complex, cells, LatticePoint{}, 1, 1);
        const std::lock_guard lock(mutex);
        out.insert(key);
    };
    EXPECT_TRUE(run_weak_root_stars(WeakRule(), library(), weak_influence(), policy, o).all_passed());
    return out;
}

// Every root-surface vertex of real installations has one of the enumerated stars (so the
// model's configurations, forcing, implications and mirror identification admit it), and
// B1-B5 hold there; the comparison can fail: without the edge and corner types the edge and
// corner vertices are missing.
TEST(WeakRootStars, RealInstallationsHaveEnumeratedStars) {
    const std::int64_t eight_u = 8 * weak_influence().unit;
    for (const auto& [policy, outside] :
         {std::pair{BoundaryPolicy::Mirror, OutsideRoot::Mirror}, std::pair{BoundaryPolicy::Coarse, OutsideRoot::Coarse}}) {
        const RealStars r = real_surface_stars(outside, enumerated_geometries(policy, 0b111), eight_u);
        std::printf("%s: %ld root-surface vertices, %ld found (%zu distinct stars), %ld missing\n", to_string(policy), r.vertices,
                    r.found, r.distinct.size(), r.missing);
        EXPECT_GT(r.vertices, 1000);
        EXPECT_EQ(r.missing, 0) << r.first_missing;
        EXPECT_EQ(r.boundary_failures, 0);
    }
    const RealStars faces_only = real_surface_stars(OutsideRoot::Mirror, enumerated_geometries(BoundaryPolicy::Mirror, 0b001), eight_u);
    EXPECT_GT(faces_only.missing, 0);
}

void print(const char* what, const WeakNearRootStarCheck& r) {
    std::printf("%s: plane sets %ld/%ld/%ld/%ld (0/1/2/3 planes through v), unchanged %ld, stars %ld (empty %ld), passed %ld, "
                "failed %ld, nodes %ld, corner pairs %ld, hits at the reach %ld\n",
                what, r.combinations[0], r.combinations[1], r.combinations[2], r.combinations[3], r.unchanged, r.stars, r.empty,
                r.passed, r.failed, r.search_nodes, r.corner_pairs, r.hits_at_reach);
    for (const auto& f : r.failures) std::printf("  %s\n", f.c_str());
}

// Coarse near the surface (W13 (f)) at parity 010: every plane set that changes the
// enumeration passes, with the pinned counts; no plane at the end of the reach matters.
TEST(WeakRootStars, CoarseNearTheSurfaceAtParity010) {
    WeakNearRootStarOptions o;
    o.parities = 1U << 2;
    const WeakNearRootStarCheck r = run_weak_near_root_stars(WeakRule(), library(), weak_influence(), o);
    print("parity 010", r);
    EXPECT_TRUE(r.all_passed()) << (r.failures.empty() ? "" : r.failures.front());
    EXPECT_EQ(r.combinations, (std::array<long, 4>{6215, 1692, 192, 0}));
    EXPECT_EQ(r.stars, 80016);
    EXPECT_EQ(r.hits_at_reach, 0);
}

// E-MR mis-oriented fails near the surface too.
TEST(WeakRootStars, CoarseNearTheSurfaceCatchesAWrongRule) {
    const test::WeakMutant misoriented(false);
    WeakNearRootStarOptions o;
    o.parities = 1U << 2;
    o.max_planes = 1;
    o.stop_after = 20;
    const WeakNearRootStarCheck r =
        run_weak_near_root_stars(misoriented, library(), weak_star_influence(misoriented, library()), o);
    EXPECT_GT(r.failed, 0);
    EXPECT_FALSE(r.all_passed());
}

// The full run, 8 parities, up to 3 planes not through v (about 80 s wall on the 2-core VM).
TEST(WeakRootStars, DISABLED_CoarseNearTheSurfaceAtEightParities) {
    const WeakNearRootStarCheck r = run_weak_near_root_stars(WeakRule(), library(), weak_influence());
    print("8 parities", r);
    EXPECT_TRUE(r.all_passed()) << (r.failures.empty() ? "" : r.failures.front());
}

}  // namespace
}  // namespace dualhex

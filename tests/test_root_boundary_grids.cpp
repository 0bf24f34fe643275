// The root-boundary enumeration's model against real installations
// (checkers/compositional_boundary.hpp): on random strongly balanced paired grids,
//  - every leaf touching the root boundary gets from install exactly the context the model
//    gives it (outside cubes on its root axes through outside_policy, both policies): so
//    the enumerated half windows include every real one;
//  - every vertex on the root surface of the installation passes check_boundary_vertices
//    (each root corner moved to the origin in turn).
#include <gtest/gtest.h>

#include <random>

#include "dualhex/checkers/compositional_boundary.hpp"
#include "dualhex/grid/refinement.hpp"
#include "dualhex/install.hpp"
#include "dualhex/install/element_templates.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "test_root_corner.hpp"

namespace dualhex {
namespace {

using detail::Index3;

// Random refinement down to `depth` (each leaf split with probability 0.4), then pairing
// and strong balance.
LeafGrid random_grid(std::mt19937& random, int depth) {
    std::vector<Leaf> leaves, todo{Leaf{}};
    while (!todo.empty()) {
        const Leaf l = todo.back();
        todo.pop_back();
        const bool split = l.level == 0 || (l.level < depth && std::uniform_real_distribution<>(0, 1)(random) < 0.4);
        if (!split) leaves.push_back(l);
        else for (const Leaf& c : children(l)) todo.push_back(c);
    }
    return pair(LeafGrid(std::move(leaves)), Balance::Strong);
}

// Status of octant cube c (level-(l-1) cell) as install computes it, folding as it does.
bool fine_as_installed(const LeafGrid& grid, int level, Index3 c, OutsideRoot outside) {
    const std::int64_t n = std::int64_t{1} << (level - 1);
    for (auto& x : c) {
        if (0 <= x && x < n) continue;
        if (outside == OutsideRoot::Coarse) return false;
        while (x < 0 || x >= n) x = x < 0 ? -1 - x : 2 * n - 1 - x;
    }
    bool fine = true;
    for (const Leaf& child : children(Leaf{level - 1, c[0], c[1], c[2]})) fine = fine && grid.is_subdivided(child);
    return fine;
}

// Over random grids: {leaves compared, contexts that differ} between install and the model
// with `policy` standing for `outside`.
std::pair<std::size_t, std::size_t> compare_contexts(OutsideRoot outside, const OutsidePolicy& policy) {
    std::mt19937 random(20261202);
    std::size_t compared = 0, differ = 0;
    for (int g = 0; g < 12; ++g) {
        const LeafGrid grid = random_grid(random, 2 + g % 3);
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const Leaf& leaf = grid.leaf(i);
            if (leaf.level == 0) continue;
            const std::int64_t last = (std::int64_t{1} << leaf.level) - 1;
            RootSides sides{};
            LatticePoint at{leaf.i, leaf.j, leaf.k}, shift{0, 0, 0};  // the model's frame: root planes at 0
            for (int a = 0; a < 3; ++a) {
                if (at[a] == 0) sides[static_cast<std::size_t>(a)] = 1;
                else if (at[a] == last) sides[static_cast<std::size_t>(a)] = -1, shift[a] = last + 1;
            }
            if (sides == RootSides{}) continue;
            const auto model = [&](Index3 o) {  // o in the model's frame
                bool in = true;
                for (std::size_t a = 0; a < 3; ++a) in = in && !((sides[a] > 0 && o[a] < 0) || (sides[a] < 0 && o[a] >= 0));
                if (!in) {
                    const OutsideOctant out = policy(o, sides, at - shift);
                    if (out.kind == OutsideOctant::Kind::Coarse) return false;
                    if (out.kind == OutsideOctant::Kind::Fine) return true;
                    o = out.copy_of;
                }
                for (int a = 0; a < 3; ++a) o[static_cast<std::size_t>(a)] += shift[a] / 2;
                return fine_as_installed(grid, leaf.level, o, outside);
            };
            ++compared;
            differ += leaf_context(grid, i, outside).neighbourhood != detail::coarse_leaf_context(at - shift, model).neighbourhood;
        }
    }
    return {compared, differ};
}

TEST(RootBoundaryGrids, InstallSeesWhatTheModelSees) {
    for (OutsideRoot outside : {OutsideRoot::Coarse, OutsideRoot::Mirror}) {
        const auto [compared, differ] =
            compare_contexts(outside, outside_policy(outside == OutsideRoot::Coarse ? BoundaryPolicy::Coarse : BoundaryPolicy::Mirror));
        EXPECT_GT(compared, 1000u);
        EXPECT_EQ(differ, 0u) << static_cast<int>(outside);
    }
    // The comparison can fail: a mirror off by one cube, and the coarse model for mirror.
    const OutsidePolicy shifted = [](const Index3& o, const RootSides& s, const LatticePoint&) {
        OutsideOctant out{OutsideOctant::Kind::Copy, o};
        for (std::size_t a = 0; a < 3; ++a)
            if ((s[a] > 0 && o[a] < 0) || (s[a] < 0 && o[a] >= 0)) out.copy_of[a] = s[a] > 0 ? -o[a] : -2 - o[a];
        return out;
    };
    EXPECT_GT(compare_contexts(OutsideRoot::Mirror, shifted).second, 0u);
    EXPECT_GT(compare_contexts(OutsideRoot::Mirror, outside_policy(BoundaryPolicy::Coarse)).second, 0u);
}

TEST(RootBoundaryGrids, EveryRootSurfaceVertexPasses) {
    const auto library = load_default_element_library();
    std::mt19937 random(7);
    for (int g = 0; g < 6; ++g) {
        const LeafGrid grid = random_grid(random, 2 + g % 3);
        for (OutsideRoot outside : {OutsideRoot::Coarse, OutsideRoot::Mirror}) {
            const InstallResult r = install(grid, StrongRule(), *library, {.outside_root = outside, .balance = Balance::Strong});
            const std::int64_t n = r.unit << r.max_level;
            // each root corner moved to the origin, the root into the positive octant (a
            // reflection keeps cells outward, transform.hpp): every face, edge and corner
            for (int corner = 0; corner < 8; ++corner) {
                const BoundaryVertexReport rep =
                    check_boundary_vertices(test::root_corner_at_origin(r.complex, n, corner), n, {1, 1, 1});
                EXPECT_TRUE(rep.ok()) << (rep.failures.empty() ? "" : rep.failures.front());
                EXPECT_GT(rep.checked, 0u);
            }
        }
    }
}

}  // namespace
}  // namespace dualhex

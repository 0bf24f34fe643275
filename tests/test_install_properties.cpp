// Property tests of the whole pipeline on random multi-level grids:
//   random octree -> pair(grid, Balance::Strong) -> install(StrongRule) with both root
//   policies -> verify_installation(...).ok(), the clipped dual all cubes (one hex per
//   vertex), every interior dual edge valence <= 6 (DESIGN.md section 6: {3, 5, 6} for
//   strongly balanced grids).
//
// Two generators, both built from tests/test_grid_generators.hpp's split trees, so every
// shrink is again an octree:
//   - dense: gen_octree(depth) (every node split with probability 1/2), depth 5 and 4;
//   - deep:  a random path of splits down to depth 6 with shallow random subtrees beside
//            it (pairing + strong balance then grade the whole neighbourhood of the path).
// On failure the paired grid is logged as a leaf file: save it and replay it with
// `dualhex install GRID.leaves -o out [--outside-root mirror]`.
//
// Size: 100 cases per property (RC_PARAMS="max_success=N" changes it), 300 grids, each
// installed twice: ~10 s of one core in Release. Under AddressSanitizer, or with
// DUALHEX_PROPERTY_SMALL=1, the depths drop (dense 3 and 2, deep 5).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>
#include <memory>
#include <sstream>

#include "dualhex/install.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/grid/refinement.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "dualhex/topology/histograms.hpp"
#include "test_grid_generators.hpp"

namespace dualhex {
namespace {

using testing::SplitTree;

bool small_sizes() {
#if defined(__SANITIZE_ADDRESS__)
    return true;
#else
    const char* env = std::getenv("DUALHEX_PROPERTY_SMALL");
    return env != nullptr && std::string(env) != "0";
#endif
}

int dense_depth() { return small_sizes() ? 3 : 5; }
int deep_depth() { return small_sizes() ? 5 : 6; }

const ElementLibrary& library() {
    static const std::shared_ptr<const ElementLibrary> lib = load_default_element_library();
    return *lib;
}

// A split node whose child `index` is `deeper` and whose other children are random trees
// of depth <= 1.
rc::Gen<SplitTree> gen_deep_tree(int depth) {
    if (depth <= 1) return testing::gen_split_tree(depth);
    return rc::gen::weightedOneOf<SplitTree>(
        {{1, rc::gen::just(SplitTree{})},
         {4, rc::gen::map(rc::gen::tuple(rc::gen::container<std::vector<SplitTree>>(8, testing::gen_split_tree(1)),
                                         rc::gen::inRange(0, 8), gen_deep_tree(depth - 1)),
                          [](std::tuple<std::vector<SplitTree>, int, SplitTree> t) {
                              auto& [kids, index, deeper] = t;
                              kids[static_cast<std::size_t>(index)] = std::move(deeper);
                              return SplitTree{std::move(kids)};
                          })}});
}

rc::Gen<LeafGrid> gen_deep_grid(int depth) {
    return rc::gen::resize(rc::kNominalSize, rc::gen::map(gen_deep_tree(depth), [](const SplitTree& t) {
                               return testing::to_grid(t);
                           }));
}

const char* name(OutsideRoot o) { return o == OutsideRoot::Mirror ? "mirror" : "coarse"; }

// Installs `paired` with the policy and checks everything; on failure logs the grid.
// Strong: the strong rule, valences <= 6; weak: the weak rule, valences <= 7 (DESIGN.md 6).
void check_installation(const LeafGrid& paired, OutsideRoot outside, Balance mode = Balance::Strong) {
    const bool weak = mode == Balance::Weak;
    const InstallResult r = weak ? install(paired, WeakRule(), library(), {.outside_root = outside, .balance = mode})
                                 : install(paired, StrongRule(), library(), {.outside_root = outside, .balance = mode});
    const InstallVerification v = verify_installation(r);
    const std::int64_t extent = r.unit << r.max_level;
    const ClippedDual dual = clipped_dual(r.complex, Incidence(r.complex), {0, 0, 0}, {extent, extent, extent});
    const auto valences = clipped_dual_edge_valences(dual);
    const int max_valence = valences.empty() ? 0 : valences.rbegin()->first;
    const bool ok = v.ok() && dual.all_cubes() && dual.hexes.size() == r.complex.n_vertices() &&
                    max_valence <= (weak ? 7 : 6);
    if (!ok) {
        std::ostringstream why;
        why << "outside-root " << name(outside) << ": " << v.summary() << "; clipped dual " << dual.hexes.size() << "/"
            << r.complex.n_vertices() << " cubes";
        if (!dual.errors.empty()) why << " (" << dual.errors.front().message << ")";
        why << "; max interior dual edge valence " << max_valence;
        RC_LOG() << why.str() << "\nreplay: dualhex install GRID.leaves -o out --outside-root " << name(outside)
                 << " --balance " << (weak ? "weak" : "strong") << "\n--- GRID.leaves (paired, "
                 << (weak ? "weakly" : "strongly") << " balanced) ---\n"
                 << format_leaves(paired, "property-test counterexample") << "--- end ---\n";
        RC_FAIL(why.str());
    }
    RC_TAG(name(outside));
}

void check_grid(const LeafGrid& grid) {
    const LeafGrid paired = pair(grid, Balance::Strong);
    RC_CLASSIFY(paired.size() > 1000, "> 1000 leaves");
    RC_CLASSIFY(paired.max_level() >= 5, "depth >= 5");
    check_installation(paired, OutsideRoot::Coarse);
    check_installation(paired, OutsideRoot::Mirror);
}

RC_GTEST_PROP(InstallProperties, DenseRandomGridsInstallToAllHex, ()) {
    check_grid(*testing::gen_octree(dense_depth()));
}

RC_GTEST_PROP(InstallProperties, ShallowDenseRandomGridsInstallToAllHex, ()) {
    check_grid(*testing::gen_octree(dense_depth() - 1));
}

RC_GTEST_PROP(InstallProperties, DeepRandomGridsInstallToAllHex, ()) {
    check_grid(*gen_deep_grid(deep_depth()));
}

// Weakly balanced grids: pair(grid, Weak), the weak rule (with the MR elements), both root
// policies; and on strongly balanced grids the weak rule places exactly what the strong one does.
void check_weak_grid(const LeafGrid& grid) {
    const LeafGrid paired = pair(grid, Balance::Weak);
    RC_CLASSIFY(!is_strongly_balanced(paired).ok, "not strongly balanced");
    check_installation(paired, OutsideRoot::Coarse, Balance::Weak);
    check_installation(paired, OutsideRoot::Mirror, Balance::Weak);
}

RC_GTEST_PROP(InstallProperties, WeaklyBalancedDenseRandomGridsInstallToAllHex, ()) {
    check_weak_grid(*testing::gen_octree(dense_depth()));
}

RC_GTEST_PROP(InstallProperties, WeaklyBalancedDeepRandomGridsInstallToAllHex, ()) {
    check_weak_grid(*gen_deep_grid(deep_depth()));
}

RC_GTEST_PROP(InstallProperties, WeakRuleEqualsStrongRuleOnStronglyBalancedGrids, ()) {
    const LeafGrid paired = pair(*testing::gen_octree(dense_depth() - 1), Balance::Strong);
    const auto contexts = leaf_contexts(paired, OutsideRoot::Coarse);
    for (const LeafContext& c : contexts) {
        RC_ASSERT(c.edge_two_finer == 0);
        RC_ASSERT(WeakRule().place(c) == StrongRule().place(c));
    }
}

// The counterexample printer round-trips: what a failure logs replays as the same grid.
TEST(InstallProperties, LoggedGridReplays) {
    const LeafGrid g = pair(testing::to_grid(SplitTree{std::vector<SplitTree>(8)}), Balance::Strong);
    const std::string text = format_leaves(g, "x");
    EXPECT_EQ(parse_leaves(text).size(), g.size());
}

}  // namespace
}  // namespace dualhex

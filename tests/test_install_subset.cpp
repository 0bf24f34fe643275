// install_leaves and the query form of leaf_context: what the distributed mesher calls on
// a rank's leaves (distributed/). A subset installed with its contexts must give each leaf
// exactly the cells the whole-grid install gives it, in the same lattice.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <vector>

#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/refinement.hpp"
#include "dualhex/install.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"

namespace dualhex {
namespace {

using CellKey = std::vector<std::vector<LatticePoint>>;  // faces as sorted point sets, sorted

CellKey cell_key(const CellComplex& k, std::size_t c) {
    CellKey key;
    for (HalfFaceHandle h : k.cell_halffaces(CellHandle(c))) {
        std::vector<LatticePoint> f;
        for (VertexHandle v : k.face_vertices(h.face())) f.push_back(k.position(v));
        std::sort(f.begin(), f.end());
        key.push_back(f);
    }
    std::sort(key.begin(), key.end());
    return key;
}

std::vector<CellKey> leaf_cells(const InstallResult& r, std::size_t n) {
    std::vector<CellKey> out;
    for (std::size_t c = r.leaf_cells[n]; c < r.leaf_cells[n + 1]; ++c) out.push_back(cell_key(r.complex, c));
    return out;
}

LeafGrid shared_grid(const char* name, Balance b) {
    const auto path = std::filesystem::path(DUALHEX_SHARED_DATA) / "grids" / name;
    if (!std::filesystem::exists(path)) return pair(LeafGrid(), b);
    return pair(read_leaf_file(path), b);
}

SubdividedQuery query_of(const LeafGrid& grid) {
    return [&grid](const Leaf& c) { return grid.is_subdivided(c); };
}

void expect_query_contexts_equal_fast(const LeafGrid& grid, std::size_t& two_finer) {
    for (OutsideRoot outside : {OutsideRoot::Coarse, OutsideRoot::Mirror}) {
        const std::vector<LeafContext> fast = leaf_contexts(grid, outside);
        for (std::size_t n = 0; n < grid.size(); ++n) {
            const LeafContext q = leaf_context(grid.leaf(n), query_of(grid), outside);
            ASSERT_EQ(q.neighbourhood, fast[n].neighbourhood) << grid.describe(n);
            ASSERT_EQ(q.edge_two_finer, fast[n].edge_two_finer) << grid.describe(n);
            two_finer += q.edge_two_finer != 0;
        }
    }
}

TEST(InstallSubset, QueryContextsEqualTheFastIndex) {
    std::size_t two_finer = 0;
    expect_query_contexts_equal_fast(shared_grid("sphere_weak_d5.leaves", Balance::Weak), two_finer);
    expect_query_contexts_equal_fast(shared_grid("sphere_strong_d5.leaves", Balance::Strong), two_finer);
    // d6 has E-MR and VC3-MR leaves: concave edges with leaves two levels finer.
    expect_query_contexts_equal_fast(shared_grid("sphere_weak_d6.leaves", Balance::Weak), two_finer);
    EXPECT_GT(two_finer, 0U) << "sphere_weak_d6 exercises the weak edge test";
}

// Leaves inside a box (a rank's share, roughly), in grid order.
std::vector<std::size_t> leaves_in_box(const LeafGrid& grid, double lo, double hi) {
    std::vector<std::size_t> out;
    for (std::size_t n = 0; n < grid.size(); ++n) {
        const Leaf& l = grid.leaf(n);
        const double x = (static_cast<double>(l.i) + 0.5) / static_cast<double>(l.extent());
        if (x >= lo && x < hi) out.push_back(n);
    }
    return out;
}

TEST(InstallSubset, ASubsetGetsTheWholeGridsCells) {
    const LeafGrid grid = shared_grid("sphere_weak_d5.leaves", Balance::Weak);
    ASSERT_GT(grid.size(), 1000U) << "needs the shared data";
    const auto library = load_default_element_library();
    const InstallResult whole = install(grid, WeakRule(), *library);
    const std::vector<std::size_t> part = leaves_in_box(grid, 0.3, 0.7);
    std::vector<Leaf> leaves;
    std::vector<LeafContext> contexts;
    for (std::size_t n : part) {
        leaves.push_back(grid.leaf(n));
        contexts.push_back(leaf_context(grid.leaf(n), query_of(grid)));
    }
    const InstallResult sub = install_leaves(leaves, contexts, grid.max_level(), WeakRule(), *library);
    ASSERT_EQ(sub.leaf_cells.size(), part.size() + 1);
    EXPECT_EQ(sub.unit, whole.unit);
    std::size_t elements = 0;
    for (std::size_t s = 0; s < part.size(); ++s) {
        ASSERT_EQ(leaf_cells(sub, s), leaf_cells(whole, part[s])) << grid.describe(part[s]);
        elements += sub.leaf_element[s] >= 0;
    }
    EXPECT_GT(elements, 100U) << "the box holds transitions";
}

TEST(InstallSubset, AWrongContextGivesOtherCells) {
    // The comparison above can fail: one leaf with a context claiming a fine neighbour.
    const LeafGrid grid = shared_grid("sphere_strong_d5.leaves", Balance::Strong);
    const auto library = load_default_element_library();
    const InstallResult whole = install(grid, StrongRule(), *library);
    std::size_t changed = 0;
    for (std::size_t n = 0; n < grid.size() && changed == 0; ++n) {
        LeafContext ctx = leaf_context(grid.leaf(n), query_of(grid));
        if (grid.leaf(n).level == 0 || ctx.neighbourhood != 0) continue;
        ctx.set_fine(-1, 0, 0);  // the octant across the leaf's face at P: a face transition
        try {
            const InstallResult one = install_leaves({grid.leaf(n)}, {ctx}, grid.max_level(), StrongRule(), *library);
            EXPECT_NE(leaf_cells(one, 0), leaf_cells(whole, n));
            ++changed;
        } catch (const InstallError& e) {
            EXPECT_NE(std::string(e.what()).find(to_string(grid.leaf(n))), std::string::npos) << e.what();
            ++changed;
        }
    }
    EXPECT_EQ(changed, 1U);
}

TEST(InstallSubset, RefusesMismatchedInput) {
    const auto library = load_default_element_library();
    EXPECT_THROW((void)install_leaves({Leaf{1, 0, 0, 0}}, {}, 1, StrongRule(), *library), std::invalid_argument);
    EXPECT_THROW((void)install_leaves({Leaf{3, 0, 0, 0}}, {LeafContext{}}, 2, StrongRule(), *library), InstallError);
}

}  // namespace
}  // namespace dualhex

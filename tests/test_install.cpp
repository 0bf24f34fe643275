// The install layer: installation into real grids (LeafGrid).
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dualhex/install.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/grid/refinement.hpp"
#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/validation.hpp"
#include "test_checkers_fixture.hpp"

namespace dualhex {
namespace {

const ElementLibrary& flat_library() {
    static const std::shared_ptr<const ElementLibrary> lib = [] {
        const auto dir = testing::write_flat_element_dir("install");
        auto l = load_element_library(dir);
        std::filesystem::remove_all(dir);
        return l;
    }();
    return *lib;
}

// Uniform level `base`, then cells (at their own level) for which split(cell) holds are
// split, repeatedly, down to `max_level`.
std::vector<Leaf> refine(int base, int max_level, const std::function<bool(const Leaf&)>& split) {
    std::vector<Leaf> out, stack;
    const std::int64_t n = std::int64_t{1} << base;
    for (std::int64_t i = 0; i < n; ++i)
        for (std::int64_t j = 0; j < n; ++j)
            for (std::int64_t k = 0; k < n; ++k) stack.push_back({base, i, j, k});
    while (!stack.empty()) {
        const Leaf c = stack.back();
        stack.pop_back();
        if (c.level < max_level && split(c)) {
            for (const Leaf& ch : children(c)) stack.push_back(ch);
        } else {
            out.push_back(c);
        }
    }
    return out;
}

// Root at level `base`, the half y < 1/2 one level finer: paired, strongly balanced,
// flat transitions only (in the interior).
LeafGrid flat_grid(int base) {
    return LeafGrid(refine(base, base + 1, [base](const Leaf& c) {
        return c.level == base && 2 * c.j < (std::int64_t{1} << base);
    }));
}

void expect_all_hex(const InstallResult& r) {
    const InstallVerification v = verify_installation(r);
    EXPECT_TRUE(v.ok()) << v.summary();
    EXPECT_EQ(v.open_faces, 0U);
    const ValidationReport report = validate(r.complex);
    std::ostringstream os;
    report.print(os, r.complex, 10);
    EXPECT_TRUE(report.ok()) << os.str();
    const DualCounts dual = count_dual(r.complex);
    EXPECT_GT(dual.interior_vertices, 0U);
    EXPECT_EQ(dual.hexes, dual.interior_vertices);
    EXPECT_EQ(dual.non_cubes, 0U);
}

TEST(CheckersInstall, FlatTwoLevelGridValidates) {
    const LeafGrid grid = flat_grid(2);  // 32 level-2 leaves above, 256 level-3 leaves below
    ASSERT_TRUE(check_installable(grid).ok);
    const InstallResult r = install(grid, FlatOnlyRule(), flat_library(), {.outside_root = OutsideRoot::Mirror});
    EXPECT_EQ(r.unit, 12);
    EXPECT_EQ(r.max_level, 3);
    const auto used = r.elements_used();
    EXPECT_EQ(used.at("F"), 16U);  // the level-2 leaves on y = 1/2
    EXPECT_EQ(used.at("hex"), 16U + 256U);
    EXPECT_EQ(r.complex.n_cells(), 16U * 4U + 16U + 256U);
    ASSERT_EQ(r.leaf_cells.size(), grid.size() + 1);
    EXPECT_EQ(r.leaf_cells.back(), r.complex.n_cells());
    expect_all_hex(r);
    // The F faces: 5 triangles, 10 quads, 5 pentagons each, shared faces counted once.
    const auto hist = face_size_histogram(r.complex);
    EXPECT_GT(hist.at(3), 0U);
    EXPECT_GT(hist.at(5), 0U);
    EXPECT_EQ(hist.count(6), 0U);
}

TEST(CheckersInstall, ThreeLevelFlatGridScalesElements) {
    // y < 1/4: level 4; 1/4 <= y < 1/2: level 3; above: level 2. Level-3 leaves are the
    // fine side of the level-2 F's and the coarse side of their own F's.
    const LeafGrid grid(refine(2, 4, [](const Leaf& c) {
        const std::int64_t n = std::int64_t{1} << c.level;  // split if the cell lies below the band limit
        return c.level == 2 ? 2 * c.j < n : 4 * c.j < n;
    }));
    ASSERT_TRUE(check_installable(grid).ok) << check_installable(grid).message;
    const InstallResult r = install(grid, FlatOnlyRule(), flat_library(), {.outside_root = OutsideRoot::Mirror});
    EXPECT_EQ(r.max_level, 4);
    EXPECT_EQ(r.elements_used().at("F"), 16U + 64U);
    expect_all_hex(r);
}

TEST(CheckersInstall, WrongReflectionIsCaught) {
    const InstallResult r = install(flat_grid(2), testing::SwappedCrossingRule(), flat_library(), {.outside_root = OutsideRoot::Mirror});
    const InstallVerification v = verify_installation(r);
    EXPECT_FALSE(v.ok());
    EXPECT_GT(v.open_faces, 0U);
    EXPECT_GT(v.validation.count(ViolationKind::VertexValence) + v.validation.count(ViolationKind::EdgeCellCount), 0U)
        << v.summary();
}

TEST(CheckersInstall, RootBoundaryCountsAsCoarseByDefault) {
    // With outside-root octant cubes coarse, a leaf on the side walls sees an edge pattern,
    // which the flat-only rule does not know: a clear error naming the leaf.
    const LeafGrid grid = flat_grid(2);
    try {
        (void)install(grid, FlatOnlyRule(), flat_library());
        FAIL() << "expected an InstallError";
    } catch (const InstallError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("no element for local pattern"), std::string::npos) << what;
        EXPECT_NE(what.find("leaf 2 "), std::string::npos) << what;
        ASSERT_TRUE(e.first().has_value());
        EXPECT_EQ(grid.leaf(*e.first()).level, 2);
    }
}

TEST(CheckersInstall, UnknownPatternInGridIsAnErrorNotACrash) {
    // Level 2, the level-1 octant at the origin one level finer: convex corner patterns.
    const LeafGrid grid(refine(2, 3, [](const Leaf& c) { return c.i < 2 && c.j < 2 && c.k < 2; }));
    ASSERT_TRUE(check_installable(grid).ok) << check_installable(grid).message;
    try {
        (void)install(grid, FlatOnlyRule(), flat_library(), {.outside_root = OutsideRoot::Mirror});
        FAIL() << "expected an InstallError";
    } catch (const InstallError& e) {
        EXPECT_NE(std::string(e.what()).find("no element for local pattern"), std::string::npos) << e.what();
    }
}

TEST(CheckersInstall, RefusesUnpairedGridNamingLeaves) {
    // Level 1 everywhere, one octant split once: its level-1 siblings are leaves.
    const LeafGrid grid(refine(1, 2, [](const Leaf& c) { return c.level == 1 && c.i == 0 && c.j == 0 && c.k == 0; }));
    ASSERT_FALSE(is_paired(grid).ok);
    try {
        (void)install(grid, FlatOnlyRule(), flat_library());
        FAIL() << "expected an InstallError";
    } catch (const InstallError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("not paired"), std::string::npos) << what;
        ASSERT_TRUE(e.first() && e.second());
        EXPECT_NE(what.find(to_string(grid.leaf(*e.first()))), std::string::npos) << what;
        EXPECT_NE(what.find(to_string(grid.leaf(*e.second()))), std::string::npos) << what;
    }
}

TEST(CheckersInstall, RefusesUnbalancedGridNamingLeaves) {
    // Level 2 everywhere; level-1 octant (0,0,0) to level 3; its level-2 cell (1,1,1) to
    // level 4: paired, but level 4 touches level 2 at x = 1/2.
    const LeafGrid grid(refine(2, 4, [](const Leaf& c) {
        if (c.level == 2) return c.i < 2 && c.j < 2 && c.k < 2;
        if (c.level == 3) return c.i / 2 == 1 && c.j / 2 == 1 && c.k / 2 == 1;
        return false;
    }));
    ASSERT_TRUE(is_paired(grid).ok) << is_paired(grid).message;
    ASSERT_FALSE(is_strongly_balanced(grid).ok);
    try {
        (void)install(grid, FlatOnlyRule(), flat_library());
        FAIL() << "expected an InstallError";
    } catch (const InstallError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("not strongly balanced"), std::string::npos) << what;
        ASSERT_TRUE(e.first() && e.second());
        EXPECT_NE(what.find(to_string(grid.leaf(*e.first()))), std::string::npos) << what;
        EXPECT_NE(what.find(to_string(grid.leaf(*e.second()))), std::string::npos) << what;
    }
}

TEST(CheckersInstall, FastContextsEqualDirectQueries) {
    std::vector<LeafGrid> grids;
    grids.push_back(flat_grid(2));
    grids.push_back(pair(LeafGrid(refine(1, 4, [](const Leaf& c) { return (c.i + 2 * c.j + 3 * c.k + c.level) % 5 == 0; })),
                         Balance::Strong));
    const std::filesystem::path d5 = std::filesystem::path(DUALHEX_SHARED_DATA) / "grids/sphere_strong_d5.leaves";
    if (std::filesystem::exists(d5)) grids.push_back(pair(read_leaf_file(d5), Balance::Strong));
    for (const LeafGrid& grid : grids) {
        ASSERT_TRUE(is_paired(grid).ok);
        for (OutsideRoot outside : {OutsideRoot::Coarse, OutsideRoot::Mirror}) {
            const std::vector<LeafContext> fast = leaf_contexts(grid, outside);
            ASSERT_EQ(fast.size(), grid.size());
            std::size_t nonzero = 0;
            for (std::size_t n = 0; n < grid.size(); ++n) {
                const LeafContext ref = leaf_context(grid, n, outside);
                ASSERT_EQ(fast[n].neighbourhood, ref.neighbourhood) << grid.describe(n) << " " << ref.describe();
                ASSERT_EQ(fast[n].application_point, ref.application_point);
                ASSERT_EQ(fast[n].direction, ref.direction);
                nonzero += ref.neighbourhood != 0;
            }
            EXPECT_GT(nonzero, 0U);
        }
    }
}

TEST(CheckersInstall, ContextOfAFlatLeaf) {
    const LeafGrid grid = flat_grid(2);
    const auto n = grid.find(Leaf{2, 1, 2, 1});  // above y = 1/2, P = (2,2,2), d = (-1,+1,-1)
    ASSERT_TRUE(n);
    const LeafContext ctx = leaf_context(grid, *n, OutsideRoot::Coarse);
    EXPECT_EQ(ctx.application_point, (LatticePoint{2, 2, 2}));
    EXPECT_EQ(ctx.direction, (std::array<int, 3>{-1, 1, -1}));
    EXPECT_EQ(ctx.local_pattern_name(), "{Y,XY,YZ,XYZ}");
    for (int i = -2; i <= 1; ++i)
        for (int j = -2; j <= 1; ++j)
            for (int k = -2; k <= 1; ++k) {
                const bool in_root = i >= -1 && i <= 0 && k >= -1 && k <= 0;  // x, z octants 0..1 of 2
                EXPECT_EQ(ctx.fine(i, j, k), in_root && j < 0 && j >= -1) << i << j << k;
            }
}

}  // namespace
}  // namespace dualhex

// Uniform grids and leaf boxes as hex complexes: counts, validity (every interior vertex
// of valence 6, every interior edge in 4 cells), and rejection of hanging nodes.
#include <gtest/gtest.h>

#include "dualhex/grid/grid_complex.hpp"
#include "dualhex/grid/input_error.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/topology/validation.hpp"

using namespace dualhex;

namespace {

LeafGrid uniform(int level) {
    const std::int64_t n = std::int64_t{1} << level;
    return LeafGrid(leaf_box(level, {0, 0, 0}, {n, n, n}));
}

}  // namespace

TEST(GridComplex, UniformGridIsAValidHexComplex) {
    for (int level = 0; level <= 3; ++level) {
        const CellComplex c = box_to_complex(uniform(level));
        const std::size_t n = std::size_t{1} << level;
        EXPECT_EQ(c.n_cells(), n * n * n);
        EXPECT_EQ(c.n_vertices(), (n + 1) * (n + 1) * (n + 1));
        EXPECT_EQ(c.n_faces(), 3 * n * n * (n + 1));
        const auto report = validate(c);
        EXPECT_TRUE(report.ok()) << "level " << level << ": " << report.violations.front().message;
        EXPECT_GT(report.checked_cells, 0u);
    }
}

TEST(GridComplex, BoxOfLeaves) {
    const auto leaves = leaf_box(4, {3, 5, 7}, {6, 7, 12});
    ASSERT_EQ(leaves.size(), 3u * 2u * 5u);
    const CellComplex c = leaves_to_complex(leaves);
    EXPECT_EQ(c.n_cells(), 30u);
    EXPECT_EQ(c.n_vertices(), 4u * 3u * 6u);
    EXPECT_TRUE(validate(c).ok());
    EXPECT_THROW((void)leaf_box(2, {0, 0, 0}, {5, 1, 1}), InputError);
    EXPECT_THROW((void)leaf_box(2, {1, 0, 0}, {1, 1, 1}), InputError);
}

TEST(GridComplex, RejectsHangingNodes) {
    const LeafGrid mixed = parse_leaves(
        "1 1 0 0\n1 0 1 0\n1 1 1 0\n1 0 0 1\n1 1 0 1\n1 0 1 1\n1 1 1 1\n"
        "2 0 0 0\n2 1 0 0\n2 0 1 0\n2 1 1 0\n2 0 0 1\n2 1 0 1\n2 0 1 1\n2 1 1 1\n",
        "mixed.leaves");
    try {
        (void)box_to_complex(mixed);
        ADD_FAILURE() << "accepted a grid with hanging nodes";
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 8);
        EXPECT_NE(std::string(e.what()).find("mixed.leaves:8: hanging nodes: leaves 1 1 0 0 (line 1) and 2 0 0 0 (line 8)"),
                  std::string::npos)
            << e.what();
    }
    const std::vector<Leaf> two{{1, 0, 0, 0}, {2, 2, 0, 0}};
    EXPECT_THROW((void)leaves_to_complex(two), InputError);
}

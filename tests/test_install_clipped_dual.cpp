// The clipped dual (topology/clipped_dual.hpp): one hex per primal vertex, boundary
// vertices included, filling the box; exact orientation checks on boxes of hexes; the
// installed shared sphere grid.
#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>
#include <set>

#include "dualhex/install.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "dualhex/topology/complex_builder.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/primitives.hpp"

namespace dualhex {
namespace {

using I128 = __int128;

// Exact signed corner Jacobians of a hex over rational points (common denominator).
std::array<I128, 8> corner_jacobians(const ClippedDual& d, const std::array<std::uint32_t, 8>& h) {
    std::int64_t lcm = 1;
    for (std::uint32_t id : h) lcm = std::lcm(lcm, d.points[id].denominator);
    std::array<std::array<I128, 3>, 8> p{};
    for (std::size_t i = 0; i < 8; ++i)
        for (int a = 0; a < 3; ++a)
            p[i][static_cast<std::size_t>(a)] =
                static_cast<I128>(d.points[h[i]].sum[a]) * (lcm / d.points[h[i]].denominator);
    auto det = [&](std::size_t o, std::size_t x, std::size_t y, std::size_t z) {
        I128 u[3], v[3], w[3];
        for (std::size_t a = 0; a < 3; ++a) u[a] = p[x][a] - p[o][a], v[a] = p[y][a] - p[o][a], w[a] = p[z][a] - p[o][a];
        return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
    };
    std::array<I128, 8> j{};
    for (std::size_t i = 0; i < 4; ++i) {
        j[i] = det(i, (i + 1) % 4, (i + 3) % 4, i + 4);
        j[i + 4] = det(i + 4, (i + 3) % 4 + 4, (i + 1) % 4 + 4, i);
    }
    return j;
}

TEST(InstallClippedDual, BoxOfHexesGivesOneCubePerVertex) {
    const std::array<int, 3> n{3, 2, 4};
    const CellComplex k = make_box({0, 0, 0}, n, 2);
    const ClippedDual d = clipped_dual(k);
    EXPECT_TRUE(d.all_cubes()) << d.errors.front().message;
    EXPECT_EQ(d.hexes.size(), k.n_vertices());
    EXPECT_EQ(d.hexes.size(), std::size_t{4 * 3 * 5});
    // Dual vertices: cells, boundary faces, crease edges (12 box edges), 8 corners.
    const std::size_t bfaces = 2 * (3 * 2 + 2 * 4 + 3 * 4), creases = 4 * (3 + 2 + 4);
    EXPECT_EQ(d.points.size(), k.n_cells() + bfaces + creases + 8);
    std::set<VertexHandle> covered(d.primal_vertex.begin(), d.primal_vertex.end());
    EXPECT_EQ(covered.size(), k.n_vertices());
    for (const auto& h : d.hexes) {
        EXPECT_EQ(std::set<std::uint32_t>(h.begin(), h.end()).size(), 8U);
        for (I128 j : corner_jacobians(d, h)) EXPECT_GT(j, 0);
    }
    // The hexes fill the box: total volume (positive corner determinant / 1 at each unit
    // hex of a uniform dual) — dual cells of a box: volumes sum to the box's.
    double volume = 0;
    for (const auto& h : d.hexes) {
        double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
        for (std::uint32_t id : h)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], d.points[id].coordinate(a));
                hi[a] = std::max(hi[a], d.points[id].coordinate(a));
            }
        volume += (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    }
    EXPECT_DOUBLE_EQ(volume, 6.0 * 4.0 * 8.0);
    // Interior dual edges are the duals of all primal faces.
    EXPECT_EQ(clipped_dual_edge_valences(d), face_size_histogram(k));
}

TEST(InstallClippedDual, InteriorVerticesMatchTheInteriorDual) {
    const CellComplex k = make_box({0, 0, 0}, {3, 3, 3});
    const Incidence inc(k);
    const ClippedDual d = clipped_dual(k, inc);
    ASSERT_TRUE(d.all_cubes());
    std::size_t interior = 0;
    for (std::size_t h = 0; h < d.hexes.size(); ++h) {
        const VertexHandle v = d.primal_vertex[h];
        if (inc.is_boundary(v)) continue;
        ++interior;
        const auto ref = dual_hex(k, inc, v);
        ASSERT_TRUE(ref.has_value());
        std::set<std::uint32_t> a(d.hexes[h].begin(), d.hexes[h].end()), b;
        for (CellHandle c : *ref) b.insert(static_cast<std::uint32_t>(c.idx));
        EXPECT_EQ(a, b);
    }
    EXPECT_EQ(interior, 8U);
}

TEST(InstallClippedDual, SingleCubeIsEightCorners) {
    const ClippedDual d = clipped_dual(make_box({0, 0, 0}, {1, 1, 1}));
    ASSERT_TRUE(d.all_cubes());
    EXPECT_EQ(d.hexes.size(), 8U);
    EXPECT_EQ(d.points.size(), 1U + 6 + 12 + 8);
    for (const auto& h : d.hexes)
        for (I128 j : corner_jacobians(d, h)) EXPECT_GT(j, 0);
}

TEST(InstallClippedDual, HoleIsReported) {
    // A 3x3x3 box without its middle cell: the hole's faces are boundary faces off the box.
    ComplexBuilder b;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int l = 0; l < 3; ++l)
                if (i != 1 || j != 1 || l != 1) b.add_cell_from_loops(cube_loops({i, j, l}));
    const CellComplex k = b.build();
    const ClippedDual d = clipped_dual(k);
    EXPECT_EQ(d.errors.size(), 8U);  // the hole's 8 corners
    EXPECT_EQ(d.hexes.size() + d.errors.size(), k.n_vertices());
    ASSERT_FALSE(d.errors.empty());
    EXPECT_NE(d.errors.front().message.find("hole"), std::string::npos) << d.errors.front().message;
}

TEST(InstallClippedDual, SphereStrongD5InstalledGivesThePaperDual) {
    const std::filesystem::path file = std::filesystem::path(DUALHEX_SHARED_DATA) / "grids" / "sphere_strong_d5.leaves";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
    const LeafGrid grid = read_leaf_file(file);
    const InstallResult r = install(grid, StrongRule(), *load_default_element_library());
    const ClippedDual d = clipped_dual(r.complex);
    EXPECT_TRUE(d.all_cubes()) << d.errors.front().message;
    EXPECT_EQ(r.complex.n_cells(), 13952U);
    EXPECT_EQ(d.hexes.size(), 14745U);
    EXPECT_EQ(d.box_max, (LatticePoint{r.unit << r.max_level, r.unit << r.max_level, r.unit << r.max_level}));
    const std::map<int, std::size_t> paper{{3, 3192}, {4, 36696}, {5, 2280}, {6, 408}};
    EXPECT_EQ(clipped_dual_edge_valences(d), paper);
}

}  // namespace
}  // namespace dualhex

// Octrees from surfaces: valid tilings, refined exactly where the surface crosses and as
// deep as the local thickness asks, then paired and strongly/weakly balanced by the grid
// layer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/grid/refinement.hpp"
#include "test_geometry_fixture.hpp"

using namespace dualhex;
using namespace dualhex::geometry;
using namespace geometry_test;
using Eigen::Vector3d;

namespace {

double total_volume(const LeafGrid& g) {
    double v = 0;
    for (const Leaf& l : g.leaves()) v += std::ldexp(1.0, -3 * l.level);
    return v;
}

/// A closed box [lo, hi] as 12 outward triangles.
TriangleSurface box_surface(const Vector3d& lo, const Vector3d& hi) {
    auto s = unit_cube_surface();
    for (auto& p : s.vertices) p = lo + p.cwiseProduct(hi - lo);
    return s;
}

TEST(SurfaceOctree, RootCubeContainsModelWithMargin) {
    const AabbTree tree(read_surface(shared_surface("cgal_cube.off")));
    const RootCube root = root_cube(tree.bounds(), 0.1);
    EXPECT_NEAR(root.size, 2.4, 1e-12);
    EXPECT_TRUE(root.origin.isApprox(Vector3d::Constant(-1.2)));
    EXPECT_TRUE(root.box(Leaf{}).contains(tree.bounds()));
    EXPECT_TRUE(root.box(Leaf{3, 7, 7, 7}).max().isApprox(Vector3d::Constant(1.2)));
}

TEST(SurfaceOctree, ThicknessOfACubeIsItsEdge) {
    const AabbTree tree(read_surface(shared_surface("cgal_cube.off")));
    for (double t : local_thickness(tree)) EXPECT_NEAR(t, 2.0, 1e-9);
}

TEST(SurfaceOctree, CubeModelTilesAndRefinesExactlyNearTheSurface) {
    const AabbTree tree(read_surface(shared_surface("cgal_cube.off")));
    SurfaceOctreeOptions opt;
    opt.max_depth = 5;
    opt.thickness_factor = 0.01;  // thickness never stops refinement: depth alone does
    const SurfaceOctree oct = surface_octree(tree, opt);
    const LeafGrid& g = oct.grid;
    EXPECT_NEAR(total_volume(g), 1.0, 1e-12);
    EXPECT_EQ(g.max_level(), 5);
    std::size_t crossing = 0, coarse_far = 0;
    for (const Leaf& l : g.leaves()) {
        const bool crosses = surface_crosses(tree, oct.root, l);
        if (crosses) {
            ++crossing;
            EXPECT_EQ(l.level, 5) << to_string(l);
        } else if (l.level < 5) {
            ++coarse_far;
        }
        // Minimal: every split node was crossed by the surface.
        if (l.level > 0) {
            EXPECT_TRUE(surface_crosses(tree, oct.root, parent(l))) << to_string(l);
        }
    }
    EXPECT_EQ(crossing, oct.crossing_leaves);
    EXPECT_GT(crossing, 0u);
    EXPECT_GT(coarse_far, 0u);
    EXPECT_LT(g.size(), std::size_t{1} << 15);  // far fewer than the uniform 32^3 grid

    const LeafGrid strong = dualhex::pair(g, Balance::Strong);
    EXPECT_TRUE(is_paired(strong).ok) << is_paired(strong).message;
    EXPECT_TRUE(is_strongly_balanced(strong).ok) << is_strongly_balanced(strong).message;
    EXPECT_GE(strong.size(), g.size());
    EXPECT_NEAR(total_volume(strong), 1.0, 1e-12);
    // It refines the octree: every octree leaf is a leaf or subdivided in the paired grid.
    for (const Leaf& l : g.leaves()) {
        EXPECT_TRUE(strong.find(l) || strong.is_subdivided(l)) << to_string(l);
    }

    const SurfaceOctree weak = paired_surface_octree(tree, Balance::Weak, opt);
    EXPECT_TRUE(is_paired(weak.grid).ok);
    EXPECT_TRUE(is_weakly_balanced(weak.grid).ok);
    EXPECT_GE(strong.size(), weak.grid.size());
}

TEST(SurfaceOctree, DefaultsOnTheCubeModelArePairedAndStronglyBalanced) {
    const AabbTree tree(read_surface(shared_surface("cgal_cube.off")));
    const SurfaceOctree oct = paired_surface_octree(tree, Balance::Strong);
    EXPECT_TRUE(is_paired(oct.grid).ok);
    EXPECT_TRUE(is_strongly_balanced(oct.grid).ok);
    // Thickness 2, root 2.4: cells must be <= 1.0, so level 2 (0.6) suffices.
    EXPECT_EQ(oct.grid.max_level(), 2);
}

TEST(SurfaceOctree, ThinSlabDrivesTheDepth) {
    // A 1 x 1 x 0.05 slab: root 1.2, cells must be <= 0.025 near the big faces: level 6.
    const AabbTree tree(box_surface(Vector3d(0, 0, 0), Vector3d(1, 1, 0.05)));
    const auto thickness = local_thickness(tree);
    EXPECT_NEAR(*std::min_element(thickness.begin(), thickness.end()), 0.05, 1e-12);
    const SurfaceOctree oct = surface_octree(tree);  // max depth 7
    EXPECT_EQ(oct.grid.max_level(), 6);
    SurfaceOctreeOptions shallow;
    shallow.max_depth = 4;
    EXPECT_EQ(surface_octree(tree, shallow).grid.max_level(), 4);
}

TEST(SurfaceOctree, RefinesEveryCrossingLeafOfARealModel) {
    const AabbTree tree(read_surface(shared_surface("cgal_joint.off")));
    SurfaceOctreeOptions opt;
    opt.max_depth = 6;
    const SurfaceOctree oct = surface_octree(tree, opt);
    EXPECT_NEAR(total_volume(oct.grid), 1.0, 1e-12);
    // A crossing leaf above max depth must satisfy the thickness bound.
    for (const Leaf& l : oct.grid.leaves()) {
        const auto tris = tree.triangles_in_box(oct.root.box(l));
        if (tris.empty() || l.level == opt.max_depth) continue;
        double thin = 1e300;
        for (int t : tris) thin = std::min(thin, oct.thickness[t]);
        EXPECT_LE(oct.root.edge(l.level), opt.thickness_factor * thin) << to_string(l);
    }
    EXPECT_EQ(oct.grid.max_level(), 6);
}

TEST(SurfaceOctree, BadOptionsAreRefused) {
    const AabbTree tree(unit_cube_surface());
    SurfaceOctreeOptions opt;
    opt.max_depth = 25;
    EXPECT_THROW((void)surface_octree(tree, opt), std::invalid_argument);
    opt.max_depth = 3;
    opt.min_depth = 4;
    EXPECT_THROW((void)surface_octree(tree, opt), std::invalid_argument);
    opt.min_depth = 3;
    EXPECT_EQ(surface_octree(tree, opt).grid.size(), 512u);  // uniform at min_depth
}

}  // namespace

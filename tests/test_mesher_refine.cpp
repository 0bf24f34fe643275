// Stage "refine" (mesher/refine_unresolved.hpp): the unresolved places between a hex mesh
// and the input, the octree split around them, and the pipeline on a slab thinner than
// its cells (no core without the stage, a mesh with it) and on a cube it leaves alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/mesher/refine_unresolved.hpp"
#include "test_geometry_fixture.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using namespace dualhex::mesher;
using geometry_test::hex_block;

namespace {

// The box [0,1] x [0,1] x [0,t], each face an n x n grid of quads (2 outward triangles
// each): samples (vertices, centroids) n per unit, as a finely tessellated input has.
geometry::TriangleSurface slab(double t, int n) {
    geometry::TriangleSurface s;
    std::map<std::array<long, 3>, int> id;
    const auto vertex = [&](const Eigen::Vector3d& p) {
        const std::array<long, 3> key{std::lround(p.x() * 1e6), std::lround(p.y() * 1e6), std::lround(p.z() * 1e6)};
        const auto [it, fresh] = id.emplace(key, static_cast<int>(s.vertices.size()));
        if (fresh) s.vertices.push_back(p);
        return it->second;
    };
    const Eigen::Vector3d size(1, 1, t);
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const auto at = [&](int a, int b) {
                Eigen::Vector3d p;
                p[axis] = side * size[axis];
                p[u] = size[u] * a / n;
                p[v] = size[v] * b / n;
                return vertex(p);
            };
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b) {
                    const int p00 = at(a, b), p10 = at(a + 1, b), p11 = at(a + 1, b + 1), p01 = at(a, b + 1);
                    if (side == 1) {  // (u, v, axis) right-handed: counter-clockwise seen from outside
                        s.triangles.push_back({p00, p10, p11});
                        s.triangles.push_back({p00, p11, p01});
                    } else {
                        s.triangles.push_back({p00, p11, p10});
                        s.triangles.push_back({p00, p01, p11});
                    }
                }
        }
    s.source = "slab";
    return s;
}

}  // namespace

TEST(RefineUnresolved, SlabIsClosedAndOutward) {
    const geometry::TriangleSurface s = slab(0.1, 4);
    EXPECT_NEAR(geometry::signed_volume(s), 0.1, 1e-12);  // outward: positive volume
}

TEST(RefineUnresolved, PlacesWhereMeshAndSurfaceAreApart) {
    const geometry::AabbTree cube(geometry_test::unit_cube_surface());
    // A hex filling the cube: nothing unresolved.
    EXPECT_TRUE(unresolved_places(hex_block(1, 1, 1).mesh, cube, 0.01).empty());
    // A hex [0.25, 0.75]^3: the cube's corners are sqrt(3)/4 from it, its faces' centres 1/4.
    const geometry::HexMesh inner = hex_block(1, 1, 1, 0.5, Eigen::Vector3d::Constant(0.25)).mesh;
    const std::vector<UnresolvedPlace> places = unresolved_places(inner, cube, 0.2);
    ASSERT_FALSE(places.empty());
    EXPECT_NEAR(places.front().distance, std::sqrt(3.0) / 4, 1e-9);
    for (std::size_t n = 1; n < places.size(); ++n) EXPECT_LE(places[n].distance, places[n - 1].distance);
    for (const auto& p : places) EXPECT_GT(p.distance, 0.2);
    EXPECT_TRUE(unresolved_places(inner, cube, 0.45).empty());
    // A hex sticking out of the cube: its far corner's place is its closest cube point.
    const geometry::HexMesh out = hex_block(1, 1, 1, 1.5).mesh;
    const std::vector<UnresolvedPlace> beyond = unresolved_places(out, cube, 0.6);
    ASSERT_FALSE(beyond.empty());
    EXPECT_NEAR(beyond.front().distance, std::sqrt(3.0) / 2, 1e-9);
    EXPECT_NEAR((beyond.front().point - Eigen::Vector3d::Ones()).norm(), 0.0, 1e-9);
    // No mesh: every input sample, each at distance `far`, one per ball.
    const std::vector<UnresolvedPlace> none = unresolved_places(geometry::HexMesh{}, cube, 0.3);
    ASSERT_FALSE(none.empty());
    for (const auto& p : none) EXPECT_EQ(p.distance, 0.3);
}

TEST(RefineUnresolved, SplitsLeavesMeetingTheBallsOnce) {
    const geometry::RootCube root;  // [0,1]^3
    const LeafGrid one(std::vector<Leaf>{Leaf{}});
    const std::vector<UnresolvedPlace> centre{{Eigen::Vector3d::Constant(0.5), 0.1}};
    EXPECT_EQ(refine_at_places(one, root, centre, 5, 1.0).grid.size(), 8u);
    EXPECT_EQ(refine_at_places(one, root, centre, 0, 1.0).split, 0u);  // the depth cap
    EXPECT_EQ(refine_at_places(one, root, {}, 5, 1.0).split, 0u);

    const std::array<Leaf, 8> root_children = children(Leaf{});
    std::vector<Leaf> eight(root_children.begin(), root_children.end());
    const LeafGrid level1(eight);
    // Ball of radius 0.45 at (0.1,0.1,0.1): the leaf holding it and its 3 face neighbours
    // (0.4 away); the others are >= 0.4 sqrt(2) away.
    const std::vector<UnresolvedPlace> corner{{Eigen::Vector3d::Constant(0.1), 0.45}};
    const LocalRefinement r = refine_at_places(level1, root, corner, 5, 1.0);
    EXPECT_EQ(r.split, 4u);
    EXPECT_EQ(r.grid.size(), 8u - 4u + 32u);
    EXPECT_EQ(refine_at_places(level1, root, corner, 5, 0.3).split, 1u);  // radius capped

    // Leaves deeper than the one holding the place are left: split leaf 0 to level 2, put
    // the place in level-1 leaf (1,1,0,0) with a ball reaching into the level-2 leaves.
    std::vector<Leaf> mixed(eight.begin() + 1, eight.end());
    for (const Leaf& c : children(eight[0])) mixed.push_back(c);
    const LeafGrid graded(mixed);
    const std::vector<UnresolvedPlace> beside{{Eigen::Vector3d(0.75, 0.25, 0.25), 0.3}};
    const LocalRefinement g = refine_at_places(graded, root, beside, 5, 1.0);
    for (const Leaf& leaf : g.grid.leaves()) EXPECT_LE(leaf.level, 2);
    EXPECT_GE(g.split, 1u);
    EXPECT_EQ(std::count_if(g.grid.leaves().begin(), g.grid.leaves().end(), [](const Leaf& l) { return l.level == 2; }),
              8 + 8 * static_cast<long>(g.split));
}

namespace {

MeshPipelineOptions slab_options(int rounds) {
    MeshPipelineOptions o;
    o.size = 0.25;             // level 3 (edge 0.15) on the slab's root cube of 1.2
    o.size_rel = 0;
    o.thickness_factor = 0;    // the thickness criterion would resolve the slab by itself
    o.curvature_angle = 0;
    o.feature_angle = 0;
    o.refine_rounds = rounds;
    return o;
}

}  // namespace

TEST(RefineUnresolved, ThinSlabLostWithoutRefinementKeptWithIt) {
    // 0.06 thick: a level-3 cell is 0.15, no dual hex fits inside.
    const geometry::AabbTree tree(slab(0.06, 16));
    EXPECT_THROW((void)mesh_surface(tree, slab_options(0)), EmptyCoreError);
    const MeshPipelineResult r = mesh_surface(tree, slab_options(4));
    EXPECT_GE(r.refine.rounds, 1);
    EXPECT_GT(r.refine.split, 0u);
    ASSERT_FALSE(r.mesh.hexes.empty());
    EXPECT_TRUE(r.topology.manifold);
    EXPECT_TRUE(r.topology.matches);
    // The mesh spans the slab: all of it within the slab, reaching its four sides.
    Eigen::AlignedBox3d box;
    for (const auto& p : r.mesh.points) box.extend(p);
    EXPECT_LT(box.max().z() - box.min().z(), 0.06 + 1e-6);
    EXPECT_GT(box.sizes().x(), 0.9);
    EXPECT_GT(box.sizes().y(), 0.9);
}

TEST(RefineUnresolved, OffOrNothingUnresolvedGivesTheSameMesh) {
    const geometry::AabbTree tree(geometry_test::unit_cube_surface());
    MeshPipelineOptions on;
    on.size = 0.25;
    on.size_rel = 0;
    on.refine_rounds = 2;
    MeshPipelineOptions off = on;
    off.refine_rounds = 0;
    const MeshPipelineResult a = mesh_surface(tree, on), b = mesh_surface(tree, off);
    ASSERT_EQ(a.refine.places.size(), 1u);
    EXPECT_EQ(a.refine.places[0], 0u);  // the cube is resolved: the stage splits nothing
    EXPECT_EQ(a.refine.rounds, 0);
    EXPECT_TRUE(b.refine.places.empty());  // off: not even looked at
    EXPECT_EQ(a.mesh.hexes, b.mesh.hexes);
    EXPECT_EQ(a.mesh.points, b.mesh.points);
}

TEST(RefineUnresolved, OptionsChecked) {
    MeshSizeOptions o;
    EXPECT_EQ(o.refine_rounds, 0);  // off by default (mesher/README.md, "refine")
    o.refine_rounds = -1;
    EXPECT_THROW(check_size_options(o), std::invalid_argument);
    o.refine_rounds = kMaxRefineRounds + 1;
    EXPECT_THROW(check_size_options(o), std::invalid_argument);
    o.refine_rounds = 1;
    o.refine_distance = 0;
    EXPECT_THROW(check_size_options(o), std::invalid_argument);
    o.refine_distance = 0.5;
    EXPECT_NO_THROW(check_size_options(o));
}

// The core, pad and check stages (mesher/select_core.hpp, pad.hpp, check_topology.hpp) on
// hand-made meshes: pad hexes are positively oriented, welded by id (shared outer points),
// their outer points on the surface; face components; the topology check accepts a
// matching boundary and names a non-manifold edge, a wrong genus and a missing component.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/inside.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/mesher/check_topology.hpp"
#include "dualhex/mesher/default_shape.hpp"
#include "dualhex/mesher/install_stage.hpp"
#include "dualhex/mesher/pad.hpp"
#include "dualhex/mesher/select_core.hpp"
#include "test_geometry_fixture.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using namespace dualhex::mesher;

namespace {

// The block [0,n]^3 of unit hexes, shrunk into the middle of the box [-1, n+1]^3.
geometry::HexMesh centred_block(int n) { return geometry_test::hex_block(n, n, n).mesh; }

void expect_padded(const PadResult& r, const geometry::HexMesh& core, const geometry::AabbTree& tree) {
    const geometry::BoundaryDefects b = geometry::boundary_defects(core.hexes, core.points.size());
    EXPECT_EQ(r.pad_hexes, b.quads.size());
    EXPECT_EQ(r.mesh.hexes.size(), core.hexes.size() + b.quads.size());
    EXPECT_EQ(r.surface_vertices, b.boundary_vertices);  // one outer point per boundary vertex: welded
    EXPECT_EQ(r.mesh.points.size(), core.points.size() + b.boundary_vertices);
    for (std::size_t v = 0; v < core.points.size(); ++v) {
        EXPECT_EQ(r.mesh.points[v], core.points[v]);  // the core is unchanged
        EXPECT_EQ(r.constraints.role[v], VertexRole::Interior);
    }
    for (std::size_t v = core.points.size(); v < r.mesh.points.size(); ++v) {
        EXPECT_EQ(r.constraints.role[v], VertexRole::Surface);
        EXPECT_LT(tree.squared_distance(r.mesh.points[v]), 1e-24) << v;
    }
    for (std::size_t h = 0; h < r.mesh.hexes.size(); ++h) EXPECT_GT(geometry::scaled_jacobian(r.mesh, h), 0.0) << h;
    const geometry::HexTopology t = geometry::check_hex_topology(r.mesh);
    EXPECT_TRUE(t.valid()) << t.summary();
    EXPECT_EQ(t.boundary_components.size(), 1u);
    EXPECT_EQ(t.boundary_components.front().euler(), 2);
}

}  // namespace

TEST(MesherPad, OneHexCoreGetsSixPadHexesOnTheBox) {
    const geometry::HexMesh core = geometry_test::hex_block(1, 1, 1, 1.0, Eigen::Vector3d(1, 1, 1)).mesh;
    const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 3.0));
    const PadResult r = pad_layer(core, tree);
    expect_padded(r, core, tree);
    EXPECT_EQ(r.mesh.hexes.size(), 7u);
    EXPECT_EQ(r.by_ray, 8u);  // the corner normals are the diagonals: they hit the box corners
    for (std::size_t v = 8; v < 16; ++v)
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(std::abs(r.mesh.points[v][a] - 1.5), 1.5, 1e-12);
}

TEST(MesherPad, BlockCoreIsWeldedByIds) {
    const geometry::HexMesh core = geometry_test::hex_block(2, 3, 2, 1.0, Eigen::Vector3d(1, 1, 1)).mesh;
    const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 5.0));
    expect_padded(pad_layer(core, tree), core, tree);
}

TEST(MesherPad, EmptyCoreIsRefused) {
    const geometry::AabbTree tree(geometry_test::unit_cube_surface());
    EXPECT_THROW((void)pad_layer({}, tree), std::invalid_argument);
}

TEST(MesherCore, FaceComponents) {
    geometry_test::HexBlock b = geometry_test::hex_block(3, 3, 1);
    std::vector<char> keep(b.mesh.hexes.size(), 0);
    keep[static_cast<std::size_t>(b.cell(0, 0, 0))] = keep[static_cast<std::size_t>(b.cell(1, 0, 0))] = 1;
    keep[static_cast<std::size_t>(b.cell(2, 1, 0))] = 1;  // touches (1,0,0) along an edge only
    keep[static_cast<std::size_t>(b.cell(2, 2, 0))] = 1;
    const geometry::HexMesh m = geometry_test::selected_mesh(b.mesh, keep);
    const std::vector<int> c = hex_face_components(m.hexes, m.points.size());
    ASSERT_EQ(c.size(), 4u);
    EXPECT_EQ(c[0], c[1]);
    EXPECT_EQ(c[2], c[3]);
    EXPECT_NE(c[0], c[2]);
    EXPECT_EQ(std::set<int>(c.begin(), c.end()), (std::set<int>{0, 1}));
}

TEST(MesherCheck, MatchingBoundaryPasses) {
    const geometry::HexMesh m = centred_block(2);
    const TopologyCheck t = check_topology(m, geometry_test::unit_cube_surface(0.0, 2.0));
    EXPECT_TRUE(t.manifold);
    EXPECT_TRUE(t.matches);
    EXPECT_TRUE(t.problems.empty());
    EXPECT_EQ(t.components(), 1u);
    EXPECT_EQ(t.euler, (std::vector<std::int64_t>{2}));
    EXPECT_EQ(t.input_euler, (std::vector<std::int64_t>{2}));
}

TEST(MesherCheck, NonManifoldEdgeFails) {
    geometry_test::HexBlock b = geometry_test::hex_block(2, 2, 1);
    std::vector<char> keep(b.mesh.hexes.size(), 0);
    keep[static_cast<std::size_t>(b.cell(0, 0, 0))] = keep[static_cast<std::size_t>(b.cell(1, 1, 0))] = 1;
    const TopologyCheck t = check_topology(geometry_test::selected_mesh(b.mesh, keep), geometry_test::unit_cube_surface());
    EXPECT_FALSE(t.manifold);
    EXPECT_FALSE(t.matches);
    EXPECT_GT(t.non_manifold_edges, 0u);
    ASSERT_FALSE(t.problems.empty());
    EXPECT_NE(t.problems.front().find("non-manifold boundary edges"), std::string::npos) << t.problems.front();
}

TEST(MesherCheck, RingAgainstABoxFailsOnTheEulerCharacteristic) {
    geometry_test::HexBlock b = geometry_test::hex_block(3, 3, 1);
    std::vector<char> keep(b.mesh.hexes.size(), 1);
    keep[static_cast<std::size_t>(b.cell(1, 1, 0))] = 0;  // a ring: a torus boundary
    const TopologyCheck t = check_topology(geometry_test::selected_mesh(b.mesh, keep), geometry_test::unit_cube_surface());
    EXPECT_TRUE(t.manifold);
    EXPECT_FALSE(t.matches);
    EXPECT_EQ(t.euler, (std::vector<std::int64_t>{0}));
    EXPECT_EQ(t.input_euler, (std::vector<std::int64_t>{2}));
    ASSERT_EQ(t.problems.size(), 1u);
    EXPECT_NE(t.problems.front().find("differs"), std::string::npos) << t.problems.front();
    // located: the ring's one boundary component, its 32 quads and bounding box
    EXPECT_NE(t.problems.front().find("component 1: 32 quads in (0 0 0)-(3 3 1)"), std::string::npos)
        << t.problems.front();
}

TEST(MesherCheck, MissingComponentFails) {
    geometry::TriangleSurface two = geometry_test::unit_cube_surface(0.0, 1.0);
    const geometry::TriangleSurface other = geometry_test::unit_cube_surface(5.0, 6.0);
    for (const auto& p : other.vertices) two.vertices.push_back(p);
    for (const auto& t : other.triangles) two.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    const TopologyCheck t = check_topology(centred_block(1), two);
    EXPECT_TRUE(t.manifold);
    EXPECT_FALSE(t.matches);
    EXPECT_EQ(t.components(), 1u);
    EXPECT_EQ(t.input_components(), 2u);
}

// The signs spread along dual edges agree with the ray test at every dual point, and the
// core rule holds for every selected hex of the real dual of the default torus.
TEST(MesherCore, EmbeddedSignsAgreeWithTheRayTest) {
    const geometry::AabbTree tree(default_shape());
    geometry::SurfaceOctreeOptions octree_options;
    octree_options.max_depth = 4;
    octree_options.thickness_factor = 0.25;
    const geometry::SurfaceOctree octree = geometry::paired_surface_octree(tree, Balance::Weak, octree_options);
    const InstallResult installed = install_schemes(octree.grid, Balance::Weak);
    const ClippedDual dual = root_clipped_dual(installed);
    const EmbeddedDual e = embed_dual(dual, root_extent(installed), octree.root, tree);
    ASSERT_EQ(e.points.size(), dual.points.size());
    std::size_t inside = 0;
    for (std::size_t i = 0; i < e.points.size(); ++i) {
        const bool ray = geometry::is_inside(tree, e.points[i]);
        EXPECT_EQ(e.signed_distance[i] > 0, ray) << i;
        // Exact inside and near the surface; far outside a lower bound of the distance
        // (the search stops at 4 x the point's longest dual edge).
        const double exact = std::sqrt(tree.squared_distance(e.points[i]));
        if (e.signed_distance[i] > 0)
            EXPECT_NEAR(e.signed_distance[i], exact, 1e-15);
        else
            EXPECT_LE(-e.signed_distance[i], exact + 1e-15);
        inside += ray ? 1 : 0;
    }
    EXPECT_GT(inside, 0u);
    const CoreSelection core = select_core(dual, e, 1);
    EXPECT_GT(core.selected_by_rule, 0u);
    EXPECT_TRUE(core.repair_manifold);
    EXPECT_EQ(core.kept_components.size(), 1u);
    const TopologyCheck t = check_topology(core.mesh, tree.surface());
    EXPECT_TRUE(t.matches) << (t.problems.empty() ? "" : t.problems.front());
}

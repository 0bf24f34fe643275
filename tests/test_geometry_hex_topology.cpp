// Exact topology of all-hex meshes (hex_topology.hpp): every check is shown meshes that
// must pass and meshes that must fail (edge- and vertex-touching solids, tori, cavities,
// mirrored, duplicated and degenerate hexes), with Euler characteristics counted by hand.
#include <gtest/gtest.h>

#include <algorithm>

#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/mesher/default_shape.hpp"
#include "test_geometry_fixture.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex::geometry;
using namespace geometry_test;
using dualhex::mesher::default_shape;

namespace {

std::vector<std::int64_t> chis(const std::vector<SurfaceComponent>& cs) {
    std::vector<std::int64_t> out;
    for (const auto& c : cs) out.push_back(c.euler());
    return out;
}

}  // namespace

TEST(HexTopology, FaceTableIsOutwardAndCoversEachEdgeTwice) {
    const HexBlock b = hex_block(1, 1, 1);
    const auto& h = b.mesh.hexes[0];
    const Eigen::Vector3d centre(0.5, 0.5, 0.5);
    std::vector<std::pair<int, int>> edges;
    for (const auto& f : kHexFaces) {
        const auto& p = b.mesh.points;
        const Eigen::Vector3d n = (p[h[f[1]]] - p[h[f[0]]]).cross(p[h[f[3]]] - p[h[f[0]]]);
        EXPECT_GT(n.dot(p[h[f[0]]] - centre), 0) << "face " << f[0] << f[1] << f[2] << f[3] << " points inward";
        for (int i = 0; i < 4; ++i) edges.emplace_back(std::min(f[i], f[(i + 1) % 4]), std::max(f[i], f[(i + 1) % 4]));
    }
    std::sort(edges.begin(), edges.end());
    for (const auto& e : kHexEdgeCorners)
        EXPECT_EQ(
            std::count(edges.begin(), edges.end(), std::pair<int, int>(std::min(e[0], e[1]), std::max(e[0], e[1]))), 2)
            << e[0] << '-' << e[1];
    EXPECT_EQ(edges.size(), 24u);
}

TEST(HexTopology, SingleHexAndBlockAreSpheres) {
    const auto one = check_hex_topology(hex_block(1, 1, 1).mesh);
    EXPECT_TRUE(one.valid()) << one.summary();
    EXPECT_EQ(one.boundary_quads, 6u);
    EXPECT_EQ(one.boundary_edges, 12u);
    EXPECT_EQ(one.boundary_vertices, 8u);
    EXPECT_EQ(chis(one.boundary_components), (std::vector<std::int64_t>{2}));
    const auto block = check_hex_topology(hex_block(3, 2, 4).mesh);
    EXPECT_TRUE(block.valid()) << block.summary();
    EXPECT_EQ(block.hex_components, 1u);
    EXPECT_EQ(block.boundary_quads, 2u * (3 * 2 + 2 * 4 + 3 * 4));
    EXPECT_EQ(chis(block.boundary_components), (std::vector<std::int64_t>{2}));
}

TEST(HexTopology, SolidTorusHasChiZeroAndCavityTwoSpheres) {
    const HexBlock b = hex_block(3, 3, 2);
    const auto ring = check_hex_topology(picked_mesh(b, [](int i, int j, int) { return !(i == 1 && j == 1); }));
    EXPECT_TRUE(ring.valid()) << ring.summary();
    EXPECT_EQ(chis(ring.boundary_components), (std::vector<std::int64_t>{0}));
    const HexBlock c = hex_block(3, 3, 3);
    const auto hollow = check_hex_topology(picked_mesh(c, [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); }));
    EXPECT_TRUE(hollow.valid()) << hollow.summary();
    EXPECT_EQ(hollow.hex_components, 1u);
    EXPECT_EQ(chis(hollow.boundary_components), (std::vector<std::int64_t>{2, 2}));
    // Two rings side by side: a genus-2 solid, chi -2.
    const HexBlock d = hex_block(5, 3, 1);
    const auto two = check_hex_topology(picked_mesh(d, [](int i, int j, int) { return !(j == 1 && (i == 1 || i == 3)); }));
    EXPECT_TRUE(two.valid()) << two.summary();
    EXPECT_EQ(chis(two.boundary_components), (std::vector<std::int64_t>{-2}));
}

TEST(HexTopology, HexesTouchingAlongAnEdgeAreNonManifold) {
    const HexBlock b = hex_block(2, 2, 1);
    const HexMesh m = picked_mesh(b, [](int i, int j, int) { return i == j; });
    const auto t = check_hex_topology(m);
    EXPECT_FALSE(t.valid());
    ASSERT_EQ(t.non_manifold_edges, 1u) << t.summary();
    ASSERT_EQ(t.first_non_manifold_edges.size(), 1u);
    const auto& e = t.first_non_manifold_edges[0];
    EXPECT_EQ(e.count, 4);  // four boundary quads at the edge
    ASSERT_EQ(e.points.size(), 2u);
    EXPECT_EQ(e.points[0].head<2>(), Eigen::Vector2d(1, 1));  // the shared vertical edge x = y = 1
    EXPECT_EQ(e.points[1].head<2>(), Eigen::Vector2d(1, 1));
    EXPECT_EQ(t.non_manifold_vertices, 2u);  // both of its ends
    EXPECT_EQ(t.hex_components, 2u);
    // One vertex-connected boundary piece: V = 14, E = 23, F = 12.
    ASSERT_EQ(t.boundary_components.size(), 1u);
    EXPECT_EQ(t.boundary_components[0].vertices, 14u);
    EXPECT_EQ(t.boundary_components[0].edges, 23u);
    EXPECT_EQ(t.boundary_components[0].euler(), 3);
    EXPECT_NE(t.summary().find("non-manifold edge: vertices"), std::string::npos) << t.summary();
}

TEST(HexTopology, HexesTouchingAtAVertexAreNonManifoldWithManifoldEdges) {
    const HexBlock b = hex_block(2, 2, 2);
    const auto t = check_hex_topology(picked_mesh(b, [](int i, int j, int k) { return i == j && j == k; }));
    EXPECT_EQ(t.non_manifold_edges, 0u) << t.summary();
    ASSERT_EQ(t.non_manifold_vertices, 1u) << t.summary();
    EXPECT_EQ(t.first_non_manifold_vertices[0].points[0], Eigen::Vector3d(1, 1, 1));
    EXPECT_EQ(t.boundary_components[0].euler(), 3);  // 15 - 24 + 12
    EXPECT_FALSE(t.valid());
    // The complement: the block without two diagonal cells; two cones meet at the centre.
    const auto c = check_hex_topology(picked_mesh(b, [](int i, int j, int k) { return !(i == j && j == k); }));
    EXPECT_EQ(c.non_manifold_edges, 0u) << c.summary();
    EXPECT_EQ(c.non_manifold_vertices, 1u) << c.summary();
    EXPECT_EQ(c.hex_components, 1u);
}

TEST(HexTopology, MirroredHexIsMisorientedAndInverted) {
    HexBlock b = hex_block(2, 1, 1);
    auto& h = b.mesh.hexes[1];
    for (int c = 0; c < 4; ++c) std::swap(h[c], h[c + 4]);  // mirrored in z
    const auto t = check_hex_topology(b.mesh);
    EXPECT_EQ(t.inverted_hexes, 1u);
    EXPECT_EQ(t.face_defects, 1u);  // the shared face, walked the same way by both
    EXPECT_GT(t.misoriented_edges, 0u);
    EXPECT_FALSE(t.valid());
}

TEST(HexTopology, DuplicatedTripledAndDegenerateHexes) {
    HexBlock b = hex_block(1, 1, 1);
    b.mesh.hexes.push_back(b.mesh.hexes[0]);
    const auto twice = check_hex_topology(b.mesh);
    EXPECT_EQ(twice.face_defects, 6u) << twice.summary();
    EXPECT_EQ(twice.boundary_quads, 0u);
    EXPECT_FALSE(twice.valid());
    HexBlock c = hex_block(2, 1, 1);
    c.mesh.hexes.push_back(c.mesh.hexes[1]);  // the shared face now has 3 hexes
    const auto thrice = boundary_defects(c.mesh.hexes, c.mesh.points.size());
    EXPECT_EQ(thrice.face_defects.size(), 6u);  // 5 faces twice the same way, 1 in 3 hexes
    EXPECT_EQ(std::count_if(thrice.face_defects.begin(), thrice.face_defects.end(),
                            [](const FaceDefect& d) { return d.hexes == 3; }),
              1);
    HexBlock d = hex_block(1, 1, 1);
    d.mesh.hexes[0][6] = d.mesh.hexes[0][5];
    const auto flat = check_hex_topology(d.mesh);
    EXPECT_EQ(flat.degenerate_hexes, 1u);
    EXPECT_EQ(flat.inverted_hexes, 1u);
    EXPECT_FALSE(flat.valid());
}

TEST(HexTopology, IdOutOfRangeNamesTheHex) {
    HexBlock b = hex_block(2, 1, 1);
    b.mesh.hexes[1][3] = 99;
    try {
        (void)check_hex_topology(b.mesh);
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("hex 1 corner 3: vertex id 99"), std::string::npos) << e.what();
    }
}

TEST(SurfaceTopology, CubeTorusAndTwoCubes) {
    EXPECT_EQ(chis(surface_topology(unit_cube_surface())), (std::vector<std::int64_t>{2}));
    EXPECT_EQ(chis(surface_topology(dualhex::mesher::default_shape())), (std::vector<std::int64_t>{0}));
    TriangleSurface two = unit_cube_surface();
    const TriangleSurface other = unit_cube_surface(3, 4);
    for (const auto& p : other.vertices) two.vertices.push_back(p);
    for (const auto& t : other.triangles) two.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    const auto cs = surface_topology(two);
    ASSERT_EQ(cs.size(), 2u);
    EXPECT_EQ(cs[0].vertices, 8u);
    EXPECT_EQ(cs[0].edges, 18u);
    EXPECT_EQ(cs[0].faces, 12u);
    two.triangles.push_back({0, 1, 16});
    EXPECT_THROW((void)surface_topology(two), std::invalid_argument);
}

TEST(SurfaceTopology, ComparisonOfMeshAndSurface) {
    const HexBlock b = hex_block(3, 3, 2);
    const auto ring = check_hex_topology(picked_mesh(b, [](int i, int j, int) { return !(i == 1 && j == 1); }));
    const auto torus = surface_topology(dualhex::mesher::default_shape());
    const auto cube = surface_topology(unit_cube_surface());
    const auto same = compare_topology(ring.boundary_components, torus);
    EXPECT_TRUE(same.same) << same.describe();
    EXPECT_TRUE(compare_topology(ring, dualhex::mesher::default_shape()).same);
    EXPECT_FALSE(compare_topology(ring, unit_cube_surface()).same);
    const auto differ = compare_topology(ring.boundary_components, cube);
    EXPECT_FALSE(differ.same);
    EXPECT_EQ(differ.describe(), "boundary chi {0} vs surface chi {2} (differ)");
    const auto hollow =
        check_hex_topology(picked_mesh(hex_block(3, 3, 3), [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); }));
    EXPECT_FALSE(compare_topology(hollow.boundary_components, cube).same);  // {2, 2} vs {2}
}

// The surface-to-hex pipeline (mesher/mesh_pipeline.hpp) at max depth <= 5: all-hex
// output (8 distinct, valid vertex ids per cell), no inverted hex on the cube and the
// default torus, the helpers (singular edges, inverted count) on hand-made meshes.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/surface.hpp"

using namespace dualhex;
using namespace dualhex::geometry;
using namespace dualhex::mesher;

namespace {

std::string model(const std::string& name) { return std::string(DUALHEX_SHARED_DATA) + "/surfaces/" + name; }

// Every cell: 8 distinct ids, all in range; every point used.
void expect_all_hex(const HexMesh& mesh) {
    ASSERT_FALSE(mesh.hexes.empty());
    std::vector<char> used(mesh.points.size(), 0);
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
        std::set<int> ids(mesh.hexes[h].begin(), mesh.hexes[h].end());
        ASSERT_EQ(ids.size(), 8u) << "hex " << h;
        for (int v : ids) {
            ASSERT_GE(v, 0);
            ASSERT_LT(static_cast<std::size_t>(v), mesh.points.size());
            used[static_cast<std::size_t>(v)] = 1;
        }
    }
    EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "unused points";
}

MeshPipelineResult run(const TriangleSurface& s, int depth, Balance balance = Balance::Weak) {
    const AabbTree tree(s);
    MeshPipelineOptions options;
    options.max_depth = depth;
    options.balance = balance;
    return mesh_surface(tree, options);
}

// A 2x2x2 block of unit cubes (27 points), VTK order.
HexMesh block() {
    HexMesh m;
    auto id = [](int i, int j, int k) { return i + 3 * j + 9 * k; };
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) m.points.emplace_back(i, j, k);
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                m.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                   id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
    return m;
}

}  // namespace

TEST(MeshPipeline, DefaultShapeIsAClosedOutwardTorus) {
    const TriangleSurface s = default_shape();
    EXPECT_TRUE(check_edges(s).closed());
    EXPECT_EQ(check_edges(s).misoriented, 0u);
    // torus volume 2 pi^2 R r^2 = 3.158 (the polygon is a bit smaller)
    EXPECT_NEAR(signed_volume(s), 2 * M_PI * M_PI * 1.0 * 0.16, 0.1);
}

TEST(MeshPipeline, DefaultShapeAllHexNoInvertedElement) {
    for (Balance b : {Balance::Weak, Balance::Strong}) {
        const MeshPipelineResult r = run(default_shape(), 5, b);
        expect_all_hex(r.mesh);
        EXPECT_GT(r.mesh.hexes.size(), 200u);
        EXPECT_GT(r.quality.min, 0.0);
        EXPECT_EQ(count_inverted(r.mesh), 0u);
        EXPECT_EQ(r.quality.hexes, r.mesh.hexes.size());
        EXPECT_GT(r.boundary_vertices, 0u);
        EXPECT_LT(r.hausdorff.max, 0.05);
        EXPECT_GT(r.hausdorff.samples, 0u);
    }
}

TEST(MeshPipeline, CubeAllHexNoInvertedElement) {
    const MeshPipelineResult r = run(read_surface(model("cgal_cube.off")), 5);
    expect_all_hex(r.mesh);
    EXPECT_GT(r.quality.min, 0.0);
    EXPECT_EQ(count_inverted(r.mesh), 0u);
    // Every boundary vertex lies on the cube's surface after projection.
    const AabbTree tree(read_surface(model("cgal_cube.off")));
    for (const auto& q : boundary_quads(r.mesh))
        for (int v : q) EXPECT_LT(tree.squared_distance(r.mesh.points[static_cast<std::size_t>(v)]), 1e-20);
}

TEST(MeshPipeline, GaoBunnyAllHex) {
    const MeshPipelineResult r = run(read_surface(model("gao_bunny_tri.off")), 5);
    expect_all_hex(r.mesh);
    EXPECT_GT(r.mesh.hexes.size(), 500u);
    EXPECT_GT(r.leaves, 1000u);
    EXPECT_GT(r.dual_hexes, r.mesh.hexes.size());
    EXPECT_GT(r.quality.min, 0.0);  // the optimiser untangles
    // The boundary is the pad's outer surface: every vertex on the input, same topology.
    EXPECT_TRUE(r.topology.matches) << (r.topology.problems.empty() ? "" : r.topology.problems.front());
    EXPECT_EQ(r.distance.share_vertices_on_surface, 1.0);
    EXPECT_EQ(r.boundary_vertices, r.distance.boundary_vertices);
    EXPECT_GE(r.optimise.min_after, r.optimise.min_before);
    EXPECT_LE(r.optimise.inverted_after, r.optimise.inverted_before);
    // A transition grid: the core has singular interior edges, all of valence 3..7 (the
    // schemes'); the pad layer adds edges of other valences where it meets the core.
    EXPECT_FALSE(r.core.singular_edge_valences.empty());
    for (const auto& [valence, count] : r.core.singular_edge_valences) {
        EXPECT_GE(valence, 3);
        EXPECT_LE(valence, 7);
        EXPECT_NE(valence, 4);
        EXPECT_GT(count, 0u);
    }
}

TEST(MeshPipeline, BadOptionsThrow) {
    const AabbTree tree(default_shape());
    MeshPipelineOptions options;
    options.max_depth = 0;
    EXPECT_THROW((void)mesh_surface(tree, options), std::invalid_argument);
}

TEST(MeshPipeline, SingularEdgesAndInvertedOnHandMadeMeshes) {
    HexMesh m = block();
    EXPECT_TRUE(interior_singular_edge_valences(m).empty());  // the centre edges have 4 hexes
    EXPECT_EQ(count_inverted(m), 0u);
    // Drop one hex: the 3 centre edges it touched now have 3 hexes but lie on boundary
    // quads, so they are not interior singular edges.
    m.hexes.pop_back();
    EXPECT_TRUE(interior_singular_edge_valences(m).empty());
    // Mirror one hex: inverted.
    HexMesh one;
    one.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    one.hexes = {{4, 5, 6, 7, 0, 1, 2, 3}};
    EXPECT_EQ(count_inverted(one), 1u);
    one.hexes = {{0, 1, 2, 3, 4, 5, 6, 7}};
    EXPECT_EQ(count_inverted(one), 0u);
}

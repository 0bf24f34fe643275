// The optimiser's deterministic work budget (mesher/optimise.hpp): the budget binds (a
// block with two tangled vertices given one visit stays tangled, with the default budget it
// is untangled; the visits done never exceed it), and the pipeline's output is bit-identical across
// runs and thread counts (the torus and the bunny at max depth 5, 1 and 3 threads).
#include <gtest/gtest.h>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/mesher/optimise.hpp"
#include "test_geometry_fixture.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using namespace dualhex::mesher;
using geometry::HexMesh;

namespace {

std::size_t id(int i, int j, int k) { return static_cast<std::size_t>(i + 4 * (j + 4 * k)); }

OptimiseResult optimise_tangled(double work_per_vertex, HexMesh& m) {
    m = geometry_test::hex_block(3, 3, 3).mesh;
    // two interior vertices through the far faces of their hexes: one visit moves only one
    m.points[id(1, 1, 1)] = {2.4, 1.5, 1.5};
    m.points[id(2, 2, 2)] = {0.6, 1.5, 1.5};
    VertexConstraints c = VertexConstraints::interior(m.points.size());
    for (std::size_t v = 0; v < m.points.size(); ++v)
        for (int a = 0; a < 3; ++a)
            if (m.points[v][a] == 0 || m.points[v][a] == 3) c.role[v] = VertexRole::Corner;
    const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 3.0));
    QualityState state = quality_state(m);
    OptimiseOptions options;
    options.work_per_vertex = work_per_vertex;
    return optimise_mesh(m, c, tree, {}, options, state);
}

MeshPipelineResult mesh_with_threads(const geometry::AabbTree& tree, int threads) {
    const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
    tbb::task_arena arena(threads);
    MeshPipelineOptions options;
    options.max_depth = 5;
    MeshPipelineResult r;
    arena.execute([&] { r = mesh_surface(tree, options); });
    return r;
}

void expect_identical(const MeshPipelineResult& a, const MeshPipelineResult& b) {
    ASSERT_EQ(a.mesh.hexes, b.mesh.hexes);
    ASSERT_EQ(a.mesh.points.size(), b.mesh.points.size());
    for (std::size_t v = 0; v < a.mesh.points.size(); ++v)
        ASSERT_EQ(a.mesh.points[v], b.mesh.points[v]) << "point " << v << " differs";  // bit for bit
    EXPECT_EQ(a.optimise.work, b.optimise.work);
    EXPECT_EQ(a.constraints.role, b.constraints.role);
}

}  // namespace

TEST(MesherBudget, TheBudgetBindsAndIsNeverExceeded) {
    HexMesh m;
    const OptimiseResult starved = optimise_tangled(1.0 / 64, m);  // 64 points: one visit
    EXPECT_EQ(starved.work_budget, 1u);
    EXPECT_LE(starved.work, 1u);
    EXPECT_TRUE(starved.hit_work_budget);
    const OptimiseResult fed = optimise_tangled(OptimiseOptions{}.work_per_vertex, m);
    EXPECT_EQ(fed.inverted_after, 0u);
    EXPECT_GT(starved.inverted_after, 0u);  // the hexes of the vertex not visited
    EXPECT_GT(fed.work, 1u);
    EXPECT_LE(fed.work, fed.work_budget);
    EXPECT_FALSE(fed.hit_time_limit);
}

TEST(MesherBudget, SameOutputAcrossRunsAndThreadCounts) {
    for (const geometry::TriangleSurface& s :
         {default_shape(), geometry::read_surface(std::string(DUALHEX_SHARED_DATA) + "/surfaces/gao_bunny_tri.off")}) {
        const geometry::AabbTree tree(s);
        const MeshPipelineResult one = mesh_with_threads(tree, 1);
        EXPECT_GT(one.optimise.work, 0u);
        expect_identical(one, mesh_with_threads(tree, 3));
        expect_identical(one, mesh_with_threads(tree, 1));
    }
}

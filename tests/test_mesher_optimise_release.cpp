// The optimise stage's release of stuck hexes (mesher/optimise_release.hpp) on a hand-made
// 3x3x3 block: a top quad with three corners on one line, the middle one a Curve vertex on
// that line between two Corners, is a flat hex no optimiser move can free (shown first);
// the release frees it by giving up the curve vertex, keeps the corners and puts the vertex
// on the surface; a block with nothing stuck is left as it is.
#include <gtest/gtest.h>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/quality.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/mesher/optimise_release.hpp"
#include "test_geometry_fixture.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using namespace dualhex::mesher;
using geometry::HexMesh;

namespace {

std::size_t id(int i, int j, int k) { return static_cast<std::size_t>(i + 4 * (j + 4 * k)); }

std::size_t count_at_most(const std::vector<double>& sj, double flat) {
    std::size_t n = 0;
    for (double s : sj) n += !(s > flat) ? 1 : 0;
    return n;
}

struct FlatTop {
    HexMesh mesh = geometry_test::hex_block(3, 3, 3).mesh;
    VertexConstraints roles = VertexConstraints::interior(mesh.points.size());
    // The diagonal of hex (1, 1, 2)'s top quad, from (1, 1, 3) to (2, 2, 3).
    FeatureCurves curves{{{1, 1, 3}, {2, 2, 3}}};
    const geometry::AabbTree tree{geometry_test::unit_cube_surface(0.0, 3.0)};
    const std::size_t a = id(1, 1, 3), middle = id(2, 1, 3), c = id(2, 2, 3);

    FlatTop() {
        for (std::size_t v = 0; v < mesh.points.size(); ++v)
            for (int axis = 0; axis < 3; ++axis)
                if (mesh.points[v][axis] == 0 || mesh.points[v][axis] == 3) roles.role[v] = VertexRole::Surface;
        roles.role[a] = roles.role[c] = VertexRole::Corner;
        mesh.points[middle] = {1.5, 1.5, 3};  // between a and c: the quad is a triangle
        roles.role[middle] = VertexRole::Curve;
        roles.curve[middle] = 0;
    }
};

}  // namespace

TEST(MesherOptimiseRelease, TheOptimiserAloneCannotFreeTheFlatHex) {
    FlatTop f;
    QualityState state = quality_state(f.mesh);
    ASSERT_LE(state.inverted, 1u);  // at most the flat hex itself (SJ exactly 0 counts as inverted)
    ASSERT_EQ(count_at_most(state.scaled_jacobian, kFlatScaledJacobian), 1u);
    OptimiseOptions options;
    options.bad_below = kFlatScaledJacobian;  // even when it chases flat hexes
    (void)optimise_mesh(f.mesh, f.roles, f.tree, f.curves, options, state);
    EXPECT_EQ(count_at_most(state.scaled_jacobian, kFlatScaledJacobian), 1u);
    EXPECT_EQ(f.mesh.points[f.middle].z(), 3.0);
}

TEST(MesherOptimiseRelease, ReleasingTheCurveVertexFreesIt) {
    FlatTop f;
    QualityState state = quality_state(f.mesh);
    const Eigen::Vector3d pa = f.mesh.points[f.a], pc = f.mesh.points[f.c];
    const ReleaseResult r =
        release_stuck_hexes(f.mesh, f.roles, f.tree, f.curves, OptimiseOptions{}, state, kFlatScaledJacobian);
    EXPECT_EQ(r.bad_before, 1u);
    EXPECT_EQ(r.bad_after, 0u);
    EXPECT_EQ(r.curves_released, 1u);
    EXPECT_EQ(r.corners_released, 0u);
    EXPECT_GT(r.work, 0u);
    EXPECT_EQ(f.roles.role[f.middle], VertexRole::Surface);
    EXPECT_EQ(f.roles.curve[f.middle], -1);
    EXPECT_EQ(f.mesh.points[f.a], pa);
    EXPECT_EQ(f.mesh.points[f.c], pc);
    EXPECT_NEAR(f.mesh.points[f.middle].z(), 3.0, 1e-12);  // on the surface, off the line
    const QualityState fresh = quality_state(f.mesh);
    EXPECT_EQ(fresh.scaled_jacobian, state.scaled_jacobian);  // the state handed on is the mesh's
    EXPECT_EQ(count_at_most(fresh.scaled_jacobian, kFlatScaledJacobian), 0u);
    EXPECT_EQ(fresh.inverted, 0u);
}

TEST(MesherOptimiseRelease, NothingStuckNothingChanged) {
    FlatTop f;
    f.mesh.points[f.middle] = {2, 1, 3};  // back on the lattice: no flat hex
    f.roles.role[f.middle] = VertexRole::Surface;
    f.roles.curve[f.middle] = -1;
    const HexMesh before = f.mesh;
    QualityState state = quality_state(f.mesh);
    const ReleaseResult r =
        release_stuck_hexes(f.mesh, f.roles, f.tree, f.curves, OptimiseOptions{}, state, kFlatScaledJacobian);
    EXPECT_EQ(r.bad_before, 0u);
    EXPECT_EQ(r.work, 0u);
    EXPECT_EQ(f.mesh.points, before.points);
}

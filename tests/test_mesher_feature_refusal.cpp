// The features stage's refusal (mesher/feature_refusal.hpp) on a hand-made 3x3x3 block:
// a snapped corner pushed through the hexes below it is undone when no repair is allowed
// (point back, role Surface, the hexes as before), a curve vertex likewise while the rest of
// its curve stays; a shallow snap the repair can untangle is kept on its corner; hexes
// inverted before the snap are left to the optimiser; mismatched inputs are refused.
#include <gtest/gtest.h>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/mesher/feature_refusal.hpp"
#include "dualhex/mesher/quality_state.hpp"
#include "test_geometry_fixture.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using namespace dualhex::mesher;
using geometry::HexMesh;

namespace {

std::size_t id(int i, int j, int k) { return static_cast<std::size_t>(i + 4 * (j + 4 * k)); }

struct Snapped {
    HexMesh mesh = geometry_test::hex_block(3, 3, 3).mesh;
    std::vector<Eigen::Vector3d> before = mesh.points;
    std::vector<double> sj_before = quality_state(mesh).scaled_jacobian;
    VertexConstraints constraints = VertexConstraints::interior(mesh.points.size());
    FeatureSnapReport report;
    FeatureCurves curves;
    Snapped() {
        for (std::size_t v = 0; v < mesh.points.size(); ++v)
            for (int a = 0; a < 3; ++a)
                if (mesh.points[v][a] == 0 || mesh.points[v][a] == 3) constraints.role[v] = VertexRole::Surface;
    }
    // What snap_features does to a vertex: moves it, gives it the role.
    void snap(std::size_t v, const Eigen::Vector3d& p, VertexRole role, int curve = -1) {
        mesh.points[v] = p;
        constraints.role[v] = role;
        constraints.curve[v] = curve;
        if (role == VertexRole::Curve) ++report.curve_vertices;
    }
    QualityState refuse(double repair_work) {
        const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 3.0));
        QualityState state = quality_state(mesh);
        FeatureRefusalOptions options;
        options.repair_work_per_vertex = repair_work;
        refuse_inverting_snaps(mesh, before, sj_before, constraints, report, tree, curves, state, options);
        EXPECT_EQ(state.scaled_jacobian, quality_state(mesh).scaled_jacobian);  // handed on current
        return state;
    }
};

}  // namespace

TEST(MesherFeatureRefusal, ACornerSnapThatInvertsIsUndoneWithoutRepair) {
    Snapped s;
    const std::size_t v = id(1, 1, 3);  // on the top face; its 4 hexes span z in [2, 3]
    s.snap(v, {1, 1, 1.5}, VertexRole::Corner);  // below their bottom faces: inverted
    ASSERT_GT(quality_state(s.mesh).inverted, 0u);
    const QualityState state = s.refuse(0);
    EXPECT_EQ(state.inverted, 0u);
    EXPECT_EQ(s.report.inverted_by_snap, 4u);
    EXPECT_EQ(s.report.repaired, 0u);
    EXPECT_EQ(s.report.corners_undone, 1u);
    EXPECT_EQ(s.report.vertices_restored, 1u);
    EXPECT_EQ(s.constraints.role[v], VertexRole::Surface);
    EXPECT_EQ(s.mesh.points[v], s.before[v]);
}

TEST(MesherFeatureRefusal, ACurveVertexThatInvertsIsGivenUpTheRestOfTheCurveStays) {
    Snapped s;
    s.curves = {{{0, 1, 3}, {3, 1, 3}}, {{0, 0, 3}, {3, 0, 3}}};
    s.snap(id(1, 1, 3), {1, 1, 1.2}, VertexRole::Curve, 0);  // inverts (off its line, for the test)
    // on no hex of the first: harmless, the same curve and another one
    s.snap(id(3, 2, 3), {3, 2.1, 3}, VertexRole::Curve, 0);
    s.snap(id(2, 3, 3), {2.1, 3, 3}, VertexRole::Curve, 1);
    s.report.path_edges = {{static_cast<int>(id(1, 1, 3)), static_cast<int>(id(2, 1, 3)), 0},
                           {static_cast<int>(id(2, 1, 3)), static_cast<int>(id(3, 2, 3)), 0},
                           {static_cast<int>(id(2, 3, 3)), static_cast<int>(id(3, 3, 3)), 1}};
    const QualityState state = s.refuse(0);
    EXPECT_EQ(state.inverted, 0u);
    EXPECT_EQ(s.report.curve_vertices_undone, 1u);
    EXPECT_EQ(s.constraints.role[id(1, 1, 3)], VertexRole::Surface);
    EXPECT_EQ(s.constraints.curve[id(1, 1, 3)], -1);
    EXPECT_EQ(s.mesh.points[id(1, 1, 3)], s.before[id(1, 1, 3)]);
    EXPECT_EQ(s.constraints.role[id(3, 2, 3)], VertexRole::Curve);  // the rest of the curve stays
    EXPECT_EQ(s.mesh.points[id(3, 2, 3)], Eigen::Vector3d(3, 2.1, 3));
    EXPECT_EQ(s.constraints.role[id(2, 3, 3)], VertexRole::Curve);  // and the other curve
    EXPECT_EQ(s.report.curve_vertices, 2u);
    ASSERT_EQ(s.report.path_edges.size(), 2u);  // the edge at the given-up vertex is gone
    EXPECT_EQ(s.report.path_edges[0].from, static_cast<int>(id(2, 1, 3)));
}

TEST(MesherFeatureRefusal, ASnapTheRepairUntanglesIsKept) {
    Snapped s;
    const std::size_t v = id(1, 1, 3);
    s.snap(v, {1, 1, 1.8}, VertexRole::Corner);  // just below z = 2: the vertex under it can make room
    ASSERT_GT(quality_state(s.mesh).inverted, 0u);
    const QualityState state = s.refuse(10);
    EXPECT_EQ(state.inverted, 0u);
    EXPECT_EQ(s.report.inverted_by_snap, 4u);
    EXPECT_EQ(s.report.repaired, 4u);
    EXPECT_EQ(s.report.corners_undone, 0u);
    EXPECT_EQ(s.constraints.role[v], VertexRole::Corner);
    EXPECT_EQ(s.mesh.points[v], Eigen::Vector3d(1, 1, 1.8));
}

TEST(MesherFeatureRefusal, HexesInvertedBeforeTheSnapAreNotItsBusiness) {
    Snapped s;
    s.before[id(1, 1, 1)] = {2.4, 1.5, 1.5};  // inverted before the snap (the pad's doing)
    s.mesh.points = s.before;
    s.sj_before = quality_state(s.mesh).scaled_jacobian;
    s.snap(id(1, 1, 3), {1.2, 1, 3}, VertexRole::Corner);
    (void)s.refuse(0);
    EXPECT_EQ(s.report.inverted_by_snap, 0u);
    EXPECT_EQ(s.constraints.role[id(1, 1, 3)], VertexRole::Corner);
}

TEST(MesherFeatureRefusal, MismatchedInputIsRefused) {
    Snapped s;
    s.before.pop_back();
    const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 3.0));
    QualityState state = quality_state(s.mesh);
    EXPECT_THROW(refuse_inverting_snaps(s.mesh, s.before, s.sj_before, s.constraints, s.report, tree, s.curves, state),
                 std::invalid_argument);
}

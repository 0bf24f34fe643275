// Pad quality (mesher/pad.hpp, core_boundary_smooth.hpp, pad_diagnosis.hpp, optimise.hpp):
// a staircase core in a sphere, smoothed first, gives less than half as many pad hexes
// below 0.3 (no core hex below the floor, interior points unmoved); a core with a concave
// edge and convex corners inside an L-shaped prism pads without inverted hexes and the
// optimiser keeps it so; the diagnostic names the causes of
// hand-made bad pad hexes (a fold of the core boundary, a collapsed top, a feature vertex)
// and counts core hexes apart.
#include <gtest/gtest.h>

#include <algorithm>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/geometry/quality.hpp"
#include "dualhex/mesher/core_boundary_smooth.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/mesher/optimise.hpp"
#include "dualhex/mesher/pad.hpp"
#include "dualhex/mesher/pad_diagnosis.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using namespace dualhex::mesher;
using geometry::HexMesh;

namespace {

// The L of cells (i, j) of an n x n x nz block without those with i >= cut and j >= cut,
// cells of edge h from `origin`.
HexMesh l_block(int n, int cut, int nz, double h, const Eigen::Vector3d& origin) {
    const geometry_test::HexBlock b = geometry_test::hex_block(n, n, nz, h, origin);
    return geometry_test::picked_mesh(b, [&](int i, int j, int) { return !(i >= cut && j >= cut); });
}

// The closed, outward triangle surface of a hex mesh's boundary (each quad split in two).
geometry::TriangleSurface boundary_surface(const HexMesh& m) {
    geometry::TriangleSurface s;
    s.vertices = m.points;
    for (const auto& q : geometry::boundary_quads(m)) {
        s.triangles.push_back({q[0], q[1], q[2]});
        s.triangles.push_back({q[0], q[2], q[3]});
    }
    return s;
}

// Surface: the L prism [0,4]^2 \ [2,4]^2 x [0,2]; core: the L inset by 0.5 (5 unit hexes,
// a concave edge at (1.5, 1.5), convex corners elsewhere).
struct LCase {
    geometry::AabbTree tree{boundary_surface(l_block(4, 2, 2, 1.0, Eigen::Vector3d::Zero()))};
    HexMesh core = l_block(3, 1, 1, 1.0, Eigen::Vector3d(0.5, 0.5, 0.5));
};

// A staircase core in a sphere: the cells of a lattice of edge 0.5 whose 8 corners are
// within radius 3.1 of the centre, inside the sphere of radius 4 (a cube's 8 x 8 faces
// pushed out onto it).
struct SphereCase {
    geometry::AabbTree tree{sphere_surface()};
    HexMesh core = staircase_ball();
    static geometry::TriangleSurface sphere_surface() {
        geometry::TriangleSurface s = boundary_surface(geometry_test::hex_block(8, 8, 8, 1.0, Eigen::Vector3d(-4, -4, -4)).mesh);
        for (auto& p : s.vertices) p = 4.0 * p.normalized();
        return s;
    }
    static HexMesh staircase_ball() {
        const geometry_test::HexBlock b = geometry_test::hex_block(14, 14, 14, 0.5, Eigen::Vector3d(-3.5, -3.5, -3.5));
        std::vector<char> keep(b.mesh.hexes.size(), 0);
        for (std::size_t h = 0; h < keep.size(); ++h) {
            keep[h] = 1;
            for (int v : b.mesh.hexes[h]) keep[h] = keep[h] && b.mesh.points[static_cast<std::size_t>(v)].norm() <= 3.1;
        }
        return geometry_test::selected_mesh(b.mesh, keep);
    }
};

std::size_t below(const std::vector<double>& sj, double t) {
    return static_cast<std::size_t>(std::count_if(sj.begin(), sj.end(), [&](double s) { return !(s >= t); }));
}

}  // namespace

TEST(MesherPadQuality, SmoothingTheStaircaseCoreGivesBetterPadHexes) {
    const SphereCase c;
    ASSERT_GT(c.core.hexes.size(), 500u);
    const std::vector<double> sj0 = geometry::scaled_jacobians(c.core);
    HexMesh smoothed = c.core;
    EXPECT_GT(smooth_core_boundary(smoothed, 5, 0.5), 0u);
    const std::vector<double> sj1 = geometry::scaled_jacobians(smoothed);
    const geometry::BoundaryDefects b = geometry::boundary_defects(c.core.hexes, c.core.points.size());
    std::vector<char> on_boundary(c.core.points.size(), 0);
    for (const auto& q : b.quads)
        for (int v : q) on_boundary[static_cast<std::size_t>(v)] = 1;
    for (std::size_t v = 0; v < c.core.points.size(); ++v) {
        if (!on_boundary[v]) {
            EXPECT_EQ(smoothed.points[v], c.core.points[v]) << v;  // only the boundary moves
        }
    }
    for (std::size_t h = 0; h < sj1.size(); ++h) EXPECT_GE(sj1[h], std::min(0.5, sj0[h]) - 1e-12) << h;  // the floor
    const PadResult raw = pad_layer(c.core, c.tree), smooth = pad_layer(smoothed, c.tree);
    const std::vector<double> q0 = geometry::scaled_jacobians(raw.mesh), q1 = geometry::scaled_jacobians(smooth.mesh);
    const PadDiagnosis d0 = diagnose_pad(raw.mesh, raw.core_hexes, raw.constraints, q0);
    const PadDiagnosis d1 = diagnose_pad(smooth.mesh, smooth.core_hexes, smooth.constraints, q1);
    EXPECT_GT(d0.pad_below, 0u) << d0.summary();  // the staircase gives bad pad hexes
    EXPECT_LT(2 * d1.pad_below, d0.pad_below) << d0.summary() << " / " << d1.summary();
    EXPECT_LE(below(q1, 0.0), below(q0, 0.0));
}

TEST(MesherPadQuality, LShapedCoreHasTheConcaveEdge) {
    const LCase c;
    ASSERT_EQ(c.core.hexes.size(), 5u);
    ASSERT_EQ(c.tree.surface().triangles.size(), 2u * (2 * 12 + 2 * 16));  // top and bottom, sides (perimeter 16)
}

TEST(MesherPadQuality, LShapedCorePadsWithoutInvertedHexes) {
    const LCase c;
    PadResult r = pad_layer(c.core, c.tree);
    QualityState state = quality_state(r.mesh);
    EXPECT_EQ(state.inverted, 0u) << diagnose_pad(r.mesh, r.core_hexes, r.constraints, state.scaled_jacobian, 0.0).summary();
    for (std::size_t v = r.core_points; v < r.mesh.points.size(); ++v)
        EXPECT_LT(c.tree.squared_distance(r.mesh.points[v]), 1e-20) << v;
    OptimiseOptions options;
    options.min_quality = 0.5;
    const OptimiseResult o = optimise_mesh(r.mesh, r.constraints, c.tree, {}, options, state);
    // Without the features stage the pad hexes across the prism's sharp edges stay poor
    // (the pipeline snaps those edges); here: none inverted, the minimum not lowered.
    EXPECT_EQ(o.inverted_after, 0u);
    EXPECT_GT(o.min_after, 0.0);
    EXPECT_GE(o.min_after, o.min_before);
}

TEST(MesherPadQuality, DiagnosisNamesAFoldAndACollapsedTop) {
    const LCase c;
    PadResult r = pad_layer(c.core, c.tree);
    // Every pad hex is bad at threshold 1.01; the pad hexes on the concave edge show it,
    // those on the convex edges too; core hexes are counted apart.
    const PadDiagnosis all = diagnose_pad(r.mesh, r.core_hexes, r.constraints, geometry::scaled_jacobians(r.mesh), 1.01);
    EXPECT_EQ(all.core_below, r.core_hexes);
    EXPECT_EQ(all.pad_below, r.pad_hexes);
    EXPECT_GT(all.concave_edge, 0u);
    EXPECT_GT(all.convex_edge, all.concave_edge);
    EXPECT_EQ(all.collapsed_top, 0u);
    EXPECT_EQ(all.feature, 0u);
    // Collapse the top of one pad hex onto one point: it is named collapsed, and inverted.
    const std::size_t h = r.core_hexes;
    for (int k = 5; k < 8; ++k) r.mesh.points[static_cast<std::size_t>(r.mesh.hexes[h][k])] = r.mesh.points[static_cast<std::size_t>(r.mesh.hexes[h][4])];
    r.constraints.role[static_cast<std::size_t>(r.mesh.hexes[h][4])] = VertexRole::Corner;
    const std::vector<double> sj = geometry::scaled_jacobians(r.mesh);
    const PadDiagnosis one = diagnose_pad(r.mesh, r.core_hexes, r.constraints, sj, 0.01);
    EXPECT_GE(one.pad_inverted, 1u);
    EXPECT_GE(one.collapsed_top, 1u);
    EXPECT_GE(one.feature, 1u);
    EXPECT_EQ(one.core_below, 0u);
}

// The whole pipeline on the L prism (a concave feature edge, convex corners) and on the
// sphere: no inverted or flat hex and no pad hex below 0.3 (the target); on the
// sphere no hex at all below 0.3. (On the L prism 72 core hexes of the dual's transition
// templates stay at 0.294: the optimiser does not yet raise them, see mesher/README.md.)
TEST(MesherPadQuality, PipelineOnTheLPrismAndTheSphere) {
    int model = 0;
    for (const geometry::TriangleSurface& s : {boundary_surface(l_block(4, 2, 2, 1.0, Eigen::Vector3d::Zero())),
                                               SphereCase::sphere_surface()}) {
        SCOPED_TRACE(++model == 1 ? "L prism" : "sphere");
        const geometry::AabbTree tree(s);
        MeshPipelineOptions options;
        options.max_depth = 5;
        const MeshPipelineResult r = mesh_surface(tree, options);
        const PadDiagnosis d = diagnose_pad(r.mesh, r.core_hexes, r.constraints, r.cell_data.scaled_jacobian);
        EXPECT_TRUE(r.inverted_hexes.empty()) << d.summary();
        EXPECT_EQ(d.pad_below, 0u) << r.mesh.hexes.size() << " hexes; " << d.summary();
        if (model == 2) {
            EXPECT_GE(r.quality.min, 0.3) << r.mesh.hexes.size() << " hexes; " << d.summary();
        }
    }
}

// The core stage keeps thin parts (mesher/select_core.hpp, core_topology.hpp): a dumbbell
// whose bar is too thin for the core rule at the size asked for; the pipeline's core must
// still reach the far end (fill hexes join it), so the surface stays close to the hex
// boundary there; and the distance diagnostic (mesh_report.hpp) names what is far and why.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/mesher/select_core.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using namespace dualhex::geometry;
using namespace dualhex::mesher;

namespace {

// A closed, outward surface: the unit squares (i, j) of `cells` (a polyomino without pinch
// points) extruded to [0, height], scaled by `unit`.
TriangleSurface extruded(const std::set<std::pair<int, int>>& cells, double height, double unit) {
    TriangleSurface s;
    std::map<std::array<int, 3>, int> id;
    const auto v = [&](int i, int j, int k) {
        const auto [it, fresh] = id.emplace(std::array<int, 3>{i, j, k}, static_cast<int>(s.vertices.size()));
        if (fresh) s.vertices.emplace_back(i * unit, j * unit, k * height * unit);
        return it->second;
    };
    const auto quad = [&](int a, int b, int c, int d) {
        s.triangles.push_back({a, b, c});
        s.triangles.push_back({a, c, d});
    };
    for (const auto& [i, j] : cells) {
        quad(v(i, j, 1), v(i + 1, j, 1), v(i + 1, j + 1, 1), v(i, j + 1, 1));  // top, +z
        quad(v(i, j, 0), v(i, j + 1, 0), v(i + 1, j + 1, 0), v(i + 1, j, 0));  // bottom, -z
        if (!cells.contains({i, j - 1})) quad(v(i, j, 0), v(i + 1, j, 0), v(i + 1, j, 1), v(i, j, 1));
        if (!cells.contains({i, j + 1})) quad(v(i + 1, j + 1, 0), v(i, j + 1, 0), v(i, j + 1, 1), v(i + 1, j + 1, 1));
        if (!cells.contains({i - 1, j})) quad(v(i, j + 1, 0), v(i, j, 0), v(i, j, 1), v(i, j + 1, 1));
        if (!cells.contains({i + 1, j})) quad(v(i + 1, j, 0), v(i + 1, j + 1, 0), v(i + 1, j + 1, 1), v(i + 1, j, 1));
    }
    return s;
}

constexpr int kBar = 4;
// Two 4x4x4 blocks joined by a bar 3 long, 4 high and kBar / 4 wide (cells of 0.25): the
// bar is a thin part.
TriangleSurface dumbbell() {
    std::set<std::pair<int, int>> cells;
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j) {
            cells.insert({i, j});
            cells.insert({i + 28, j});
        }
    for (int i = 16; i < 28; ++i)
        for (int j = 4; j < 4 + kBar; ++j) cells.insert({i, j});
    return extruded(cells, 16, 0.25);
}

MeshPipelineResult coarse_run(const TriangleSurface& s, double fill_margin) {
    const AabbTree tree(s);
    MeshPipelineOptions o;
    o.size_rel = 0.1;          // cells about the bar's width: the rule cannot fit it
    o.thickness_factor = 0;    // no refinement by thickness, no curvature refinement
    o.curvature_angle = 0;
    o.feature_angle = 0;
    o.optimise.work_per_vertex = 10;
    o.core.fill_margin = fill_margin;
    return mesh_surface(tree, o);
}

}  // namespace

TEST(MesherCoreFill, DumbbellIsClosedAndOutward) {
    const TriangleSurface s = dumbbell();
    EXPECT_TRUE(check_edges(s).closed());
    EXPECT_EQ(check_edges(s).misoriented, 0u);
    EXPECT_NEAR(signed_volume(s), (512 + 12 * kBar) * 16 / 64.0, 1e-9);
    const auto topo = surface_topology(s);
    ASSERT_EQ(topo.size(), 1u);
    EXPECT_EQ(topo[0].euler(), 2);
}

TEST(MesherCoreFill, DiagnosticNamesTheDroppedEnd) {
    const TriangleSurface s = dumbbell();
    // The bar has no dual hex inside at this size: the rule's core is the two ends, apart;
    // one is dropped and the pad spans the other: the surface there is far from the boundary.
    const MeshPipelineResult cut = coarse_run(s, 0.02);
    ASSERT_EQ(cut.core.dropped_components.size(), 1u) << "the bar is not thin for the rule";
    EXPECT_GT(cut.distance.relative(cut.distance.surface_to_mesh.max), 0.1);
    // The diagnostic sees it: far points whose inside hexes were dropped with their part.
    ASSERT_FALSE(cut.far_points.empty());
    const FarSurfacePoint& far = cut.far_points.front();
    EXPECT_EQ(far.cause, CoreFate::DroppedPart);
    EXPECT_GT(far.distance, 0.1 * cut.distance.diagonal);
    EXPECT_GT(far.point.x(), 7.0);  // on the dropped end
    EXPECT_EQ(far.fates[static_cast<std::size_t>(CoreFate::Core)], 0u);
    EXPECT_FALSE(far.on_hex_boundary);
    // Per side the places are farthest first, and none is within another's distance.
    const auto& fp = cut.far_points;
    for (std::size_t i = 1; i < fp.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) {
            if (fp[i].on_hex_boundary != fp[j].on_hex_boundary) continue;
            EXPECT_LE(fp[i].distance, fp[j].distance);
            EXPECT_GT((fp[i].point - fp[j].point).norm(), fp[j].distance);
        }
    EXPECT_GE(far.distance, 0.5 * cut.distance.surface_to_mesh.max);
}

namespace {

// Signed distance (> 0 inside) to the box [lo, hi], exact inside (the nearest face).
double box_depth(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
    return std::min((p - lo).minCoeff(), (hi - p).minCoeff());
}

}  // namespace

// A dumbbell on a 9x3x3 block of unit hexes: two 3x3x3 ends deep enough for the rule, a
// bar along the middle row whose corners are only 0.05 inside (a thin part: fill, not
// rule). The rule's selection is two parts; the input has one. Without fill one end is
// dropped; with fill the bar joins it, and the bar's hexes stay (they are the neck).
TEST(MesherCoreFill, ThinNeckKeepsTheFarEnd) {
    const geometry_test::HexBlock b = geometry_test::hex_block(9, 3, 3);
    ClippedDual dual;
    dual.points.resize(b.mesh.points.size());
    for (const auto& h : b.mesh.hexes) {
        std::array<std::uint32_t, 8> q{};
        for (int c = 0; c < 8; ++c) q[static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(h[static_cast<std::size_t>(c)]);
        dual.hexes.push_back(q);
    }
    EmbeddedDual e;
    e.points = b.mesh.points;
    for (const Eigen::Vector3d& p : e.points) {
        const double ends = std::max(box_depth(p, Eigen::Vector3d::Constant(-0.2), Eigen::Vector3d::Constant(3.2)),
                                     box_depth(p, Eigen::Vector3d(5.8, -0.2, -0.2), Eigen::Vector3d(9.2, 3.2, 3.2)));
        const double bar = box_depth(p, Eigen::Vector3d(2.5, 0.95, 0.95), Eigen::Vector3d(6.5, 2.05, 2.05));
        e.signed_distance.push_back(std::max(ends, bar));
    }
    const std::vector<geometry::SurfaceComponent> sphere{{4, 6, 4}};  // one component, chi 2
    CoreOptions no_fill;
    no_fill.fill_margin = -1;
    const CoreSelection cut = select_core(dual, e, sphere, no_fill, true);
    EXPECT_EQ(cut.mesh.hexes.size(), 27u);
    EXPECT_EQ(cut.dropped_components, (std::vector<std::size_t>{27}));
    EXPECT_EQ(std::count(cut.fate.begin(), cut.fate.end(), CoreFate::DroppedPart), 27);
    const CoreSelection kept = select_core(dual, e, sphere, CoreOptions{}, true);
    EXPECT_EQ(kept.mesh.hexes.size(), 57u);
    EXPECT_TRUE(kept.dropped_components.empty());
    EXPECT_TRUE(kept.topology_controlled);
    EXPECT_EQ(kept.topology_fill, 3u);
    EXPECT_EQ(kept.topology_rejoined, 27u);
    for (int i = 3; i < 6; ++i) EXPECT_EQ(kept.fate[static_cast<std::size_t>(b.cell(i, 1, 1))], CoreFate::FillCore);
    const auto topo = geometry::check_hex_topology(kept.mesh, 0);
    EXPECT_EQ(topo.non_manifold_edges + topo.non_manifold_vertices, 0u);
    EXPECT_TRUE(geometry::compare_topology(topo.boundary_components, sphere).same);
    // A fill too shallow for the bar (0.06 > 0.05) joins nothing.
    CoreOptions shallow;
    shallow.fill_margin = 0.06;
    EXPECT_EQ(select_core(dual, e, sphere, shallow, true).mesh.hexes.size(), 27u);
}

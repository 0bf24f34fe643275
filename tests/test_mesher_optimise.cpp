// The optimise stage (mesher/optimise.hpp) on hand-made blocks: a tangled block is
// untangled, a good block is not made worse, roles are honoured (surface vertices on the
// surface, curve vertices on their polyline, corners fixed), and on random perturbations
// the contract holds (inverted never more, minimum scaled Jacobian never lower).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/quality.hpp"
#include "dualhex/mesher/optimise.hpp"
#include "dualhex/mesher/surface_smooth.hpp"
#include "../mesher/src/optimise_detail.hpp"  // internal: the final contract check
#include "test_geometry_fixture.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using namespace dualhex::mesher;
using geometry::HexMesh;

namespace {

// A 3x3x3 block of unit hexes in [0,3]^3; vertex id of lattice point (i,j,k).
int id(int i, int j, int k) { return i + 4 * (j + 4 * k); }

bool on_box_boundary(const Eigen::Vector3d& p) {
    for (int a = 0; a < 3; ++a)
        if (p[a] == 0 || p[a] == 3) return true;
    return false;
}

// Roles: boundary vertices of the block get `boundary_role`, the rest Interior.
VertexConstraints block_roles(const HexMesh& m, VertexRole boundary_role) {
    VertexConstraints c = VertexConstraints::interior(m.points.size());
    for (std::size_t v = 0; v < m.points.size(); ++v)
        if (on_box_boundary(m.points[v])) c.role[v] = boundary_role;
    return c;
}

OptimiseResult run(HexMesh& m, const VertexConstraints& c, const FeatureCurves& curves = {},
                   double target = 0.9) {
    const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 3.0));
    QualityState state = quality_state(m);
    OptimiseOptions options;
    options.min_quality = target;
    const OptimiseResult r = optimise_mesh(m, c, tree, curves, options, state);
    // The state handed on is the mesh's.
    const QualityState fresh = quality_state(m);
    EXPECT_EQ(fresh.inverted, state.inverted);
    EXPECT_EQ(fresh.scaled_jacobian, state.scaled_jacobian);
    return r;
}

}  // namespace

TEST(MesherOptimise, UntanglesAnInteriorVertexPushedThroughAFace) {
    HexMesh m = geometry_test::hex_block(3, 3, 3).mesh;
    m.points[static_cast<std::size_t>(id(1, 1, 1))] = {2.4, 1.5, 1.5};  // through the hexes' far faces
    ASSERT_GT(count_inverted(m), 0u);
    const OptimiseResult r = run(m, block_roles(m, VertexRole::Corner));
    EXPECT_GT(r.inverted_before, 0u);
    EXPECT_EQ(r.inverted_after, 0u);
    EXPECT_TRUE(r.untangle_kept);
    EXPECT_GT(r.untangle_sweeps, 0);
    EXPECT_EQ(count_inverted(m), 0u);
    EXPECT_GT(geometry::summarize(geometry::scaled_jacobians(m)).min, 0.5);
}

TEST(MesherOptimise, AGoodBlockIsNotMadeWorse) {
    HexMesh m = geometry_test::hex_block(3, 3, 3).mesh;
    const HexMesh before = m;
    const OptimiseResult r = run(m, block_roles(m, VertexRole::Corner), {}, 1.0);
    EXPECT_EQ(r.inverted_before, 0u);
    EXPECT_EQ(r.untangle_sweeps, 0);
    EXPECT_DOUBLE_EQ(r.min_after, 1.0);
    for (std::size_t v = 0; v < m.points.size(); ++v) EXPECT_LT((m.points[v] - before.points[v]).norm(), 1e-12);
}

TEST(MesherOptimise, SurfaceVerticesStayOnTheSurfaceAndCornersStay) {
    HexMesh m = geometry_test::hex_block(3, 3, 3).mesh;
    VertexConstraints c = block_roles(m, VertexRole::Surface);
    const std::size_t corner = static_cast<std::size_t>(id(0, 0, 0));
    c.role[corner] = VertexRole::Corner;
    // Shear the top face's inner vertices along the surface and tangle the interior.
    m.points[static_cast<std::size_t>(id(1, 1, 3))] += Eigen::Vector3d(0.7, 0.6, 0);
    m.points[static_cast<std::size_t>(id(2, 2, 2))] = {0.8, 0.9, 1.1};
    const Eigen::Vector3d corner_before = m.points[corner];
    const OptimiseResult r = run(m, c);
    EXPECT_EQ(r.inverted_after, 0u);
    EXPECT_GE(r.min_after, r.min_before);
    const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 3.0));
    const double diagonal = std::sqrt(27.0);
    for (std::size_t v = 0; v < m.points.size(); ++v)
        if (c.role[v] == VertexRole::Surface) EXPECT_LT(std::sqrt(tree.squared_distance(m.points[v])), 1e-12 * diagonal) << v;
    EXPECT_EQ(m.points[corner], corner_before);
}

TEST(MesherOptimise, CurveVerticesStayOnTheirPolyline) {
    HexMesh m = geometry_test::hex_block(3, 3, 3).mesh;
    VertexConstraints c = block_roles(m, VertexRole::Corner);
    // The block's edge x = 0, y = 0 as a polyline; its two inner vertices slide on it.
    const FeatureCurves curves{{{0, 0, 0}, {0, 0, 1.5}, {0, 0, 3}}};
    for (int k : {1, 2}) {
        c.role[static_cast<std::size_t>(id(0, 0, k))] = VertexRole::Curve;
        c.curve[static_cast<std::size_t>(id(0, 0, k))] = 0;
    }
    m.points[static_cast<std::size_t>(id(0, 0, 1))] = {0, 0, 2.2};  // past its neighbour: tangled
    ASSERT_GT(count_inverted(m), 0u);
    const OptimiseResult r = run(m, c, curves);
    EXPECT_LT(r.inverted_after, r.inverted_before);
    for (int k : {1, 2}) {
        const Eigen::Vector3d& p = m.points[static_cast<std::size_t>(id(0, 0, k))];
        EXPECT_EQ(p.x(), 0.0);
        EXPECT_EQ(p.y(), 0.0);
    }
}

TEST(MesherOptimise, BadConstraintsAreRefused) {
    HexMesh m = geometry_test::hex_block(1, 1, 1).mesh;
    VertexConstraints c = VertexConstraints::interior(m.points.size());
    c.role[3] = VertexRole::Curve;
    c.curve[3] = 2;  // no such curve
    const geometry::AabbTree tree(geometry_test::unit_cube_surface());
    QualityState state = quality_state(m);
    EXPECT_THROW((void)optimise_mesh(m, c, tree, {}, {}, state), std::invalid_argument);
    c = VertexConstraints::interior(3);  // wrong size
    EXPECT_THROW((void)optimise_mesh(m, c, tree, {}, {}, state), std::invalid_argument);
}

// Random moves of the interior vertices (some tangling), interior free, boundary Surface.
RC_GTEST_PROP(MesherOptimise, NeverMoreInvertedNeverLowerMinimum, ()) {
    HexMesh m = geometry_test::hex_block(3, 3, 3).mesh;
    const VertexConstraints c = block_roles(m, VertexRole::Surface);
    const auto moves = *rc::gen::container<std::vector<int>>(24, rc::gen::inRange(-90, 91));
    int n = 0;
    for (int k = 1; k <= 2; ++k)
        for (int j = 1; j <= 2; ++j)
            for (int i = 1; i <= 2; ++i, n += 3)
                m.points[static_cast<std::size_t>(id(i, j, k))] +=
                    Eigen::Vector3d(moves[n], moves[n + 1], moves[n + 2]) / 100.0;
    const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 3.0));
    QualityState state = quality_state(m);
    OptimiseOptions options;
    options.min_quality = 0.8;
    options.quality_sweeps = 5;
    const OptimiseResult r = optimise_mesh(m, c, tree, {}, options, state);
    RC_ASSERT(r.inverted_after <= r.inverted_before);
    RC_ASSERT(r.min_after >= r.min_before);
    RC_ASSERT(count_inverted(m) == r.inverted_after);
}

// The surface part of the smooth stage: surface vertices pulled apart along a face come
// back towards even spacing, on the surface, without new inverted hexes; interior and
// corner vertices do not move.
TEST(MesherSmooth, SurfaceSmoothingStaysOnTheSurface) {
    HexMesh m = geometry_test::hex_block(3, 3, 3).mesh;
    VertexConstraints c = block_roles(m, VertexRole::Surface);
    const std::size_t corner = static_cast<std::size_t>(id(0, 0, 3));
    c.role[corner] = VertexRole::Corner;
    const std::size_t moved = static_cast<std::size_t>(id(1, 1, 3));
    m.points[moved] += Eigen::Vector3d(0.8, 0.7, 0);  // along the top face
    const HexMesh before = m;
    const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 3.0));
    const FeatureCurves curves;
    const VertexDomain domain{tree, curves, c};
    QualityState state = quality_state(m);
    const std::size_t inverted = state.inverted;
    EXPECT_GT(smooth_surface(m, domain, 5, state), 0);
    EXPECT_LE(state.inverted, inverted);
    EXPECT_EQ(state.scaled_jacobian, quality_state(m).scaled_jacobian);
    EXPECT_LT((m.points[moved] - Eigen::Vector3d(1, 1, 3)).norm(), (before.points[moved] - Eigen::Vector3d(1, 1, 3)).norm());
    for (std::size_t v = 0; v < m.points.size(); ++v) {
        if (c.role[v] == VertexRole::Surface) EXPECT_LT(tree.squared_distance(m.points[v]), 1e-24) << v;
        if (c.role[v] != VertexRole::Surface) EXPECT_EQ(m.points[v], before.points[v]) << v;
    }
}

// A deliberately tangled block: every interior vertex of a 4x4x4 block scattered by up to
// 0.9 of an edge (a fixed pseudo-random sequence), the boundary held: many hexes inverted,
// the untangler (with the phases after it) leaves none.
TEST(MesherOptimise, UntanglesAScrambledBlock) {
    HexMesh m = geometry_test::hex_block(4, 4, 4).mesh;
    VertexConstraints c = VertexConstraints::interior(m.points.size());
    std::uint32_t seed = 12345;
    auto next = [&] {  // a small LCG: the same scramble on every platform
        seed = seed * 1664525u + 1013904223u;
        return static_cast<double>(seed >> 8) / static_cast<double>(1u << 24) * 2 - 1;
    };
    for (std::size_t v = 0; v < m.points.size(); ++v) {
        const Eigen::Vector3d p = m.points[v];
        const bool boundary = p.minCoeff() == 0 || p.maxCoeff() == 4;
        if (boundary) {
            c.role[v] = VertexRole::Corner;
            continue;
        }
        for (int a = 0; a < 3; ++a) m.points[v][a] += 0.9 * next();
    }
    const std::size_t tangled = count_inverted(m);
    ASSERT_GE(tangled, 10u);
    const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 4.0));
    QualityState state = quality_state(m);
    OptimiseOptions options;
    options.min_quality = 0.5;
    const OptimiseResult r = optimise_mesh(m, c, tree, {}, options, state);
    EXPECT_EQ(r.inverted_before, tangled);
    EXPECT_EQ(r.inverted_after, 0u);
    EXPECT_FALSE(r.restored);
    EXPECT_EQ(count_inverted(m), 0u);
    EXPECT_GT(geometry::summarize(geometry::scaled_jacobians(m)).min, 0.2);
}

// Two hexes that share only their free corner v, every other corner held, placed so that
// no position of v makes both valid: the untangler frees one (fewer inverted hexes, kept)
// and the other stays inverted, no lower than the start's minimum, so nothing is restored.
TEST(MesherOptimise, OfTwoHexesThatCannotBothBeValidOneIsFreed) {
    HexMesh m;
    auto add_cube = [&](const Eigen::Vector3d& lo) {
        std::array<int, 8> ids{};
        const int base = static_cast<int>(m.points.size());
        const Eigen::Vector3d corner[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
        for (int k = 0; k < 8; ++k) {
            m.points.push_back(lo + corner[k]);
            ids[static_cast<std::size_t>(k)] = base + k;
        }
        m.hexes.push_back(ids);
    };
    add_cube({1.1, 0, 0});   // valid only with v.x > 1.1 (its corner 6 would be (2.1, 1, 1))
    add_cube({-0.3, 1, 1});  // valid only with v.x < 0.7 (its corner 0 would be (-0.3, 1, 1))
    const int v = 6;        // A's corner 6 and B's corner 0: one vertex at (1, 1, 1)
    m.points[6] = {1, 1, 1};
    m.hexes[1][0] = v;
    VertexConstraints c = VertexConstraints::interior(m.points.size());
    for (std::size_t p = 0; p < m.points.size(); ++p)
        if (p != static_cast<std::size_t>(v)) c.role[p] = VertexRole::Corner;
    const std::vector<Eigen::Vector3d> start = m.points;
    QualityState state = quality_state(m);
    ASSERT_EQ(state.inverted, 2u);
    const geometry::AabbTree tree(geometry_test::unit_cube_surface(0.0, 3.0));
    const OptimiseResult r = optimise_mesh(m, c, tree, {}, {}, state);
    EXPECT_TRUE(r.untangle_kept);
    EXPECT_FALSE(r.restored);
    EXPECT_EQ(r.inverted_after, 1u);
    EXPECT_GE(r.min_after, r.min_before);
    EXPECT_NE(m.points, start);
    EXPECT_EQ(state.scaled_jacobian, quality_state(m).scaled_jacobian);
}

// The final contract check (optimise_detail.hpp restore_if_worse) on contrived phase
// results: a phase that lowered the minimum (no hex inverted) or inverted a hex is undone,
// one that raised the minimum is kept.
TEST(MesherOptimise, TheFinalContractCheckRestoresTheStart) {
    HexMesh m = geometry_test::hex_block(3, 3, 3).mesh;
    const std::size_t v = static_cast<std::size_t>(id(1, 1, 1));
    m.points[v] += Eigen::Vector3d(0.2, 0.1, 0);
    const std::vector<Eigen::Vector3d> start = m.points;
    const QualityState start_state = quality_state(m);
    auto phase = [&](const Eigen::Vector3d& to) {  // "a phase": v moved to `to`
        m.points[v] = to;
        QualityState state = quality_state(m);
        const bool restored = detail::restore_if_worse(m, start, start_state, state);
        EXPECT_EQ(state.scaled_jacobian, quality_state(m).scaled_jacobian);
        return restored;
    };
    EXPECT_TRUE(phase({1.35, 1.2, 1.1}));  // valid, a lower minimum
    EXPECT_EQ(m.points, start);
    EXPECT_TRUE(phase({2.5, 1, 1}));  // through the far faces: inverted
    EXPECT_EQ(m.points, start);
    EXPECT_FALSE(phase({1, 1, 1}));  // back to the cube's lattice: better
    EXPECT_EQ(m.points[v], Eigen::Vector3d(1, 1, 1));
}

namespace {

// What a VertexStarQuality reads: the optimiser's context over mesh m (all vertices
// interior, the cube [0,3]^3 as surface, bad below 0.5).
struct StarFixture {
    const geometry::AabbTree tree{geometry_test::unit_cube_surface(0.0, 3.0)};
    const VertexConstraints constraints;
    const FeatureCurves no_curves;
    const VertexDomain domain{tree, no_curves, constraints};
    const detail::VertexHexes incidence;
    std::vector<double> sj;
    detail::OptimiseContext context;
    explicit StarFixture(HexMesh& m)
        : constraints(VertexConstraints::interior(m.points.size())),
          incidence(m),
          sj(geometry::scaled_jacobians(m)),
          context{m, domain, incidence, sj, 0.5, 0} {}
};

}  // namespace

// The quality phase's per-visit cache (VertexStarQuality) against local_quality, the plain
// evaluation, on scrambled blocks: the same counts and the same minimum, bit for bit, at
// random trial positions and at ones that collapse an edge (a term of length 0). And the
// comparison sees a difference: a star kept while a neighbour moves (outside its contract)
// disagrees with local_quality there.
RC_GTEST_PROP(MesherOptimise, TheVertexStarCacheEqualsTheFullEvaluation, ()) {
    HexMesh m = geometry_test::hex_block(3, 3, 3).mesh;
    for (auto& p : m.points) {
        if (on_box_boundary(p)) continue;
        for (int a = 0; a < 3; ++a) p[a] += *rc::gen::inRange(-450, 451) / 1000.0;
    }
    StarFixture f(m);
    detail::OptimiseContext& c = f.context;
    const auto v = static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(m.points.size())));
    const detail::VertexStarQuality star(c, v);
    std::vector<Eigen::Vector3d> trials{m.points[v]};
    for (int t = 0; t < 8; ++t) {
        Eigen::Vector3d d;
        for (int a = 0; a < 3; ++a) d[a] = *rc::gen::inRange(-1500, 1501) / 1000.0;
        trials.push_back(m.points[v] + d);
    }
    const auto& first_hex = m.hexes[static_cast<std::size_t>(f.incidence.hex[f.incidence.start[v]])];
    const int other = first_hex[0] == static_cast<int>(v) ? first_hex[6] : first_hex[0];
    trials.push_back(m.points[static_cast<std::size_t>(other)]);  // on another vertex: an edge of length 0
    for (const Eigen::Vector3d& x : trials) {
        const detail::LocalQuality a = star.at(x), b = detail::local_quality(c, v, x);
        RC_ASSERT(a.inverted == b.inverted);
        RC_ASSERT(a.bad == b.bad);
        RC_ASSERT(std::bit_cast<std::uint64_t>(a.min) == std::bit_cast<std::uint64_t>(b.min));
    }
}

TEST(MesherOptimise, AStaleVertexStarIsSeenToDiffer) {
    HexMesh m = geometry_test::hex_block(3, 3, 3).mesh;
    StarFixture f(m);
    detail::OptimiseContext& c = f.context;
    const auto v = static_cast<std::size_t>(id(1, 1, 1));
    const detail::VertexStarQuality star(c, v);
    const Eigen::Vector3d x = m.points[v] + Eigen::Vector3d(0.1, -0.05, 0.02);
    EXPECT_EQ(star.at(x).min, detail::local_quality(c, v, x).min);
    m.points[static_cast<std::size_t>(id(2, 2, 2))] += Eigen::Vector3d(0.3, 0.2, -0.1);  // a vertex of v's hexes
    EXPECT_NE(star.at(x).min, detail::local_quality(c, v, x).min);
}

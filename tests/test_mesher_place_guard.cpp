// The optimiser's contract judged place by place (mesher/src/place_guard.hpp) on a hand-made
// 11x2x2 block with three separate places, one interior vertex each, moved from a "before"
// to an "after" position: A ends with more hexes <= flat, C with a lower minimum, B better
// in all three. The whole block after has fewer hexes <= flat and a higher minimum than
// before (a check on the whole run accepts it); the guard puts A and C back and keeps B.
// A place neither worse nor better is kept.
#include <gtest/gtest.h>

#include <algorithm>

#include "../mesher/src/place_guard.hpp"
#include "dualhex/geometry/quality.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using geometry::HexMesh;

namespace {

constexpr double kFlat = 0.9;  // a high "flat" threshold, so that moderate moves cross it

std::size_t id(int i, int j, int k) { return static_cast<std::size_t>(i + 12 * (j + 3 * k)); }

std::size_t count_at_most(const std::vector<double>& sj, double flat) {
    return static_cast<std::size_t>(std::count_if(sj.begin(), sj.end(), [&](double s) { return !(s > flat); }));
}

struct ThreePlaces {
    HexMesh mesh = geometry_test::hex_block(11, 2, 2).mesh;
    const std::size_t a = id(2, 1, 1), b = id(5, 1, 1), c = id(8, 1, 1);
    std::vector<Eigen::Vector3d> before;
    std::vector<double> sj_before;

    ThreePlaces() {
        mesh.points[a] += Eigen::Vector3d(0.3, 0.3, 0);  // min 0.63, 4 of its 8 hexes <= 0.9
        mesh.points[b] += Eigen::Vector3d(0.6, 0, 0);    // min 0.74, 8 <= 0.9
        mesh.points[c] += Eigen::Vector3d(0.45, 0, 0);   // min 0.83, 8 <= 0.9
        before = mesh.points;
        sj_before = geometry::scaled_jacobians(mesh);
        mesh.points[a] += Eigen::Vector3d(0.15, -0.3, 0);  // to +0.45 x: min 0.83, 8 <= 0.9 (more)
        mesh.points[b] += Eigen::Vector3d(-0.3, 0, 0);     // to +0.3 x: min 0.92, none (better)
        mesh.points[c] += Eigen::Vector3d(-0.25, 0.2, 0.2);  // to +0.2 (1,1,1): min 0.65 (lower), 2
    }
};

}  // namespace

TEST(MesherPlaceGuard, TheWholeBlockLooksBetter) {
    ThreePlaces f;
    const std::vector<double> after = geometry::scaled_jacobians(f.mesh);
    EXPECT_LT(count_at_most(after, kFlat), count_at_most(f.sj_before, kFlat));
    EXPECT_GT(*std::min_element(after.begin(), after.end()), *std::min_element(f.sj_before.begin(), f.sj_before.end()));
}

TEST(MesherPlaceGuard, PutsBackThePlacesLeftWorse) {
    ThreePlaces f;
    const std::vector<Eigen::Vector3d> moved = f.mesh.points;
    const auto r = mesher::detail::restore_worse_places(f.mesh, f.before, f.sj_before, kFlat);
    EXPECT_EQ(r.places, 3u);
    EXPECT_EQ(r.restored, 2u);
    EXPECT_EQ(f.mesh.points[f.a], f.before[f.a]);
    EXPECT_EQ(f.mesh.points[f.b], moved[f.b]);
    EXPECT_EQ(f.mesh.points[f.c], f.before[f.c]);
    // A and C's hexes are as before bit for bit; none is worse than before.
    const std::vector<double> sj = geometry::scaled_jacobians(f.mesh);
    for (std::size_t h = 0; h < sj.size(); ++h) EXPECT_GE(sj[h], f.sj_before[h]) << "hex " << h;
}

TEST(MesherPlaceGuard, APlaceNeitherWorseNorBetterIsKept) {
    // One hex whose corner 0 sits on corner 1 (an edge of length 0: scaled Jacobian exactly
    // 0), moved onto corner 3: still exactly 0, so neither worse nor better.
    HexMesh mesh = geometry_test::hex_block(1, 1, 1).mesh;
    const auto corner = [&](int k) { return static_cast<std::size_t>(mesh.hexes[0][static_cast<std::size_t>(k)]); };
    const std::size_t v = corner(0);
    mesh.points[v] = mesh.points[corner(1)];
    const std::vector<Eigen::Vector3d> before = mesh.points;
    const std::vector<double> sj_before = geometry::scaled_jacobians(mesh);
    ASSERT_EQ(sj_before[0], 0.0);
    mesh.points[v] = mesh.points[corner(3)];
    ASSERT_EQ(geometry::scaled_jacobian(mesh, 0), 0.0);
    HexMesh kept = mesh;
    const auto r = mesher::detail::restore_worse_places(kept, before, sj_before, kFlat);
    EXPECT_EQ(r.places, 1u);
    EXPECT_EQ(r.restored, 0u);
    EXPECT_EQ(kept.points[v], mesh.points[v]);
}

TEST(MesherPlaceGuard, NothingMovedNothingToJudge) {
    ThreePlaces f;
    f.mesh.points = f.before;
    const auto r = mesher::detail::restore_worse_places(f.mesh, f.before, f.sj_before, kFlat);
    EXPECT_EQ(r.places, 0u);
    EXPECT_EQ(f.mesh.points, f.before);
}

// Scaled Jacobian (cube = 1 at any scale/rotation, inverted < 0, degenerate 0, known
// skewed values), the summary, boundary quads and the boundary-to-surface distance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dualhex/geometry/quality.hpp"
#include "test_geometry_fixture.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex::geometry;
using namespace geometry_test;
using Eigen::Vector3d;

namespace {

std::array<Vector3d, 8> unit_hex(double lo = 0, double hi = 1) {
    return {Vector3d(lo, lo, lo), Vector3d(hi, lo, lo), Vector3d(hi, hi, lo), Vector3d(lo, hi, lo),
            Vector3d(lo, lo, hi), Vector3d(hi, lo, hi), Vector3d(hi, hi, hi), Vector3d(lo, hi, hi)};
}

HexMesh block(int n, double size) { return hex_block(n, n, n, size / n).mesh; }  // n^3 hexes filling [0, size]^3

TEST(ScaledJacobian, CubeIsOne) {
    EXPECT_NEAR(scaled_jacobian(unit_hex()), 1.0, 1e-15);
    auto h = unit_hex(-3, 7);
    const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    for (auto& p : h) p = r * p + Vector3d(5, -2, 1);
    EXPECT_NEAR(scaled_jacobian(h), 1.0, 1e-12);
}

TEST(ScaledJacobian, InvertedAndDegenerate) {
    auto h = unit_hex();
    std::swap(h[0], h[4]);  // corner order mirrored in z at one corner pair...
    std::swap(h[1], h[5]);
    std::swap(h[2], h[6]);
    std::swap(h[3], h[7]);  // ... i.e. the whole hex mirrored: inverted
    EXPECT_NEAR(scaled_jacobian(h), -1.0, 1e-15);
    auto poked = unit_hex();
    poked[6] = Vector3d(0.2, 0.2, 0.2);  // a corner pushed through the hex
    EXPECT_LT(scaled_jacobian(poked), 0.0);
    auto flat = unit_hex();
    flat[4] = flat[0];
    EXPECT_EQ(scaled_jacobian(flat), 0.0);
}

TEST(ScaledJacobian, ShearedHexHasTheSineOfItsAngle) {
    auto h = unit_hex();
    for (int c = 4; c < 8; ++c) h[c].x() += 1.0;  // top shifted by 1: 45 degrees
    EXPECT_NEAR(scaled_jacobian(h), std::sin(std::numbers::pi / 4), 1e-12);
}

TEST(Quality, SummaryCounts) {
    const auto s = summarize({1.0, 0.5, 0.1, -0.2});
    EXPECT_EQ(s.hexes, 4u);
    EXPECT_DOUBLE_EQ(s.min, -0.2);
    EXPECT_DOUBLE_EQ(s.mean, 0.35);
    EXPECT_DOUBLE_EQ(s.share_negative, 0.25);
    EXPECT_DOUBLE_EQ(s.share_below_02, 0.5);
    EXPECT_EQ(summarize({}).hexes, 0u);
    const HexMesh m = block(3, 1.0);
    const auto sj = scaled_jacobians(m);
    ASSERT_EQ(sj.size(), 27u);
    EXPECT_NEAR(summarize(sj).min, 1.0, 1e-12);
}

TEST(Quality, BoundaryQuadsAreOutward) {
    const HexMesh m = block(3, 3.0);
    const auto quads = boundary_quads(m);
    EXPECT_EQ(quads.size(), 54u);
    for (const auto& q : quads) {
        const Vector3d c = (m.points[q[0]] + m.points[q[1]] + m.points[q[2]] + m.points[q[3]]) / 4;
        const Vector3d n = (m.points[q[1]] - m.points[q[0]]).cross(m.points[q[2]] - m.points[q[0]]);
        EXPECT_GT(n.dot(c - Vector3d(1.5, 1.5, 1.5)), 0.0);
    }
}

TEST(Quality, BoundaryToSurfaceDistance) {
    const AabbTree tree(unit_cube_surface());
    const HexMesh exact = block(2, 1.0);
    const auto d0 = boundary_to_surface_distance(exact, tree);
    EXPECT_EQ(d0.samples, 24u + 26u);  // 24 boundary quads + 26 boundary vertices
    EXPECT_NEAR(d0.max, 0.0, 1e-15);
    HexMesh bigger = block(2, 1.0);
    for (auto& p : bigger.points) p = 1.1 * p;  // corner (1.1,1.1,1.1) is 0.1*sqrt(3) away
    const auto d1 = boundary_to_surface_distance(bigger, tree);
    EXPECT_NEAR(d1.max, 0.1 * std::sqrt(3.0) / std::sqrt(3.0), 1e-12);  // / bbox diagonal sqrt(3)
    EXPECT_GT(d1.mean, 0.0);
    EXPECT_LT(d1.mean, d1.max);
}

}  // namespace

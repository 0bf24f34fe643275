// Feature detection (geometry/feature_curves.hpp): the cube's 12 edges and 8 corners, no
// feature on a smooth icosphere, curves split at corners, closed loops, the turn rule,
// short chains dropped whole (min_chain_length),
// bad input refused, and the polyline helpers.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <map>
#include <set>

#include "dualhex/geometry/feature_curves.hpp"
#include "test_geometry_fixture.hpp"

using namespace dualhex::geometry;
using geometry_test::unit_cube_surface;

namespace {

// Icosphere: the icosahedron subdivided `levels` times, vertices on the unit sphere.
TriangleSurface icosphere(int levels) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    TriangleSurface s;
    for (const auto& p : {Eigen::Vector3d(-1, t, 0), Eigen::Vector3d(1, t, 0), Eigen::Vector3d(-1, -t, 0),
                          Eigen::Vector3d(1, -t, 0), Eigen::Vector3d(0, -1, t), Eigen::Vector3d(0, 1, t),
                          Eigen::Vector3d(0, -1, -t), Eigen::Vector3d(0, 1, -t), Eigen::Vector3d(t, 0, -1),
                          Eigen::Vector3d(t, 0, 1), Eigen::Vector3d(-t, 0, -1), Eigen::Vector3d(-t, 0, 1)})
        s.vertices.push_back(p.normalized());
    s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<int, int>, int> mid;
        auto midpoint = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            const auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            s.vertices.push_back((s.vertices[static_cast<std::size_t>(a)] + s.vertices[static_cast<std::size_t>(b)])
                                     .normalized());
            return mid[key] = static_cast<int>(s.vertices.size()) - 1;
        };
        std::vector<std::array<int, 3>> next;
        for (const auto& f : s.triangles) {
            const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            next.insert(next.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
        }
        s.triangles = std::move(next);
    }
    return s;
}

// A triangular prism over a regular n-gon of radius 1, height 1 (caps fanned from a centre).
TriangleSurface ngon_prism(int n) {
    TriangleSurface s;
    for (int k = 0; k < 2; ++k) {
        for (int i = 0; i < n; ++i) {
            const double a = 2 * M_PI * i / n;
            s.vertices.emplace_back(std::cos(a), std::sin(a), k);
        }
    }
    const int c0 = 2 * n, c1 = 2 * n + 1;
    s.vertices.emplace_back(0, 0, 0);
    s.vertices.emplace_back(0, 0, 1);
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        s.triangles.push_back({c0, j, i});
        s.triangles.push_back({c1, n + i, n + j});
        s.triangles.push_back({i, j, n + j});
        s.triangles.push_back({i, n + j, n + i});
    }
    return s;
}

TEST(GeometryFeatures, CubeHasTwelveEdgesEightCornersTwelveCurves) {
    const FeatureSet f = detect_features(unit_cube_surface());
    EXPECT_EQ(f.edges.size(), 12u);  // the 6 face diagonals are flat
    EXPECT_EQ(f.corners.size(), 8u);
    ASSERT_EQ(f.curves.size(), 12u);
    for (const auto& c : f.curves) {
        EXPECT_FALSE(c.closed);
        ASSERT_EQ(c.vertices.size(), 2u);  // corner to corner, one edge each
        EXPECT_NEAR(c.length(), 1.0, 1e-12);
        EXPECT_EQ(c.points.size(), c.vertices.size());
    }
    EXPECT_EQ(f.patches, 6);  // the faces (each two triangles across a flat diagonal)
    ASSERT_EQ(f.patch.size(), 12u);
    for (const auto& c : f.curves) {  // two different faces on its two sides
        EXPECT_GE(c.sides[0], 0);
        EXPECT_GE(c.sides[1], 0);
        EXPECT_NE(c.sides[0], c.sides[1]);
    }
    for (const auto& e : f.edges) {  // an edge of the cube: its ends differ in one coordinate
        const Eigen::Vector3d d = unit_cube_surface().vertices[static_cast<std::size_t>(e[0])] -
                                  unit_cube_surface().vertices[static_cast<std::size_t>(e[1])];
        EXPECT_NEAR(d.lpNorm<1>(), 1.0, 1e-12);
    }
}

TEST(GeometryFeatures, SmoothIcosphereHasNone) {
    const FeatureSet f = detect_features(icosphere(3));  // 1280 triangles, ~4.6 degrees per edge
    EXPECT_TRUE(f.edges.empty());
    EXPECT_TRUE(f.corners.empty());
    EXPECT_TRUE(f.curves.empty());
    EXPECT_EQ(f.patches, 1);
    // the bare icosahedron bends by ~41.8 degrees per edge: every edge is a feature at 30
    FeatureOptions low;
    low.angle_degrees = 30;
    const FeatureSet coarse = detect_features(icosphere(0), low);
    EXPECT_EQ(coarse.edges.size(), 30u);
    EXPECT_EQ(coarse.corners.size(), 12u);  // valence 5
    EXPECT_EQ(coarse.curves.size(), 30u);
}

TEST(GeometryFeatures, PrismCapsAreClosedLoopsWithoutCorners) {
    // 24-gon: the side bends by 15 degrees per edge (smooth), the cap rims by 90 (sharp),
    // each rim turns by 15 degrees per vertex (no corner): two closed curves.
    const FeatureSet f = detect_features(ngon_prism(24));
    EXPECT_EQ(f.edges.size(), 48u);
    EXPECT_TRUE(f.corners.empty());
    ASSERT_EQ(f.curves.size(), 2u);
    EXPECT_EQ(f.patches, 3);  // two caps and the side
    for (const auto& c : f.curves) {
        EXPECT_TRUE(c.closed);
        // the side is on the same side of neither rim: walked counter-clockwise seen from
        // outside, the bottom rim (z = 0) has the side on one hand and the top rim on the other
        EXPECT_NE(c.sides[0], c.sides[1]);
        EXPECT_EQ(c.vertices.size(), 24u);
        EXPECT_EQ(std::set<int>(c.vertices.begin(), c.vertices.end()).size(), 24u);
        EXPECT_NEAR(c.length(), 24 * 2 * std::sin(M_PI / 24), 1e-12);
    }
    // a square prism: the vertical edges are sharp too, 8 corners, 12 curves
    const FeatureSet square = detect_features(ngon_prism(4));
    EXPECT_EQ(square.corners.size(), 8u);
    EXPECT_EQ(square.curves.size(), 12u);
    EXPECT_EQ(square.patches, 6);
}

TEST(GeometryFeatures, CurveSidesFollowOrientation) {
    // the unit cube's edge from (0,0,0) to (1,0,0): seen from outside the bottom face
    // (z = 0) is on one hand and the front face (y = 0) on the other; reversing the walk
    // swaps them
    const TriangleSurface cube = unit_cube_surface();
    const FeatureSet f = detect_features(cube);
    auto patch_with_normal = [&](const Eigen::Vector3d& n) {
        for (std::size_t t = 0; t < cube.triangles.size(); ++t) {
            const auto& tri = cube.triangles[t];
            auto p = [&](int i) { return cube.vertices[static_cast<std::size_t>(tri[static_cast<std::size_t>(i)])]; };
            const Eigen::Vector3d m = (p(1) - p(0)).cross(p(2) - p(0));
            if (m.normalized().isApprox(n)) return f.patch[t];
        }
        return -1;
    };
    const int bottom = patch_with_normal({0, 0, -1}), front = patch_with_normal({0, -1, 0});
    ASSERT_GE(bottom, 0);
    ASSERT_GE(front, 0);
    for (const auto& c : f.curves) {
        if (std::minmax(c.vertices[0], c.vertices[1]) != std::minmax(0, 1)) continue;
        // walking 0 -> 1 (+x) with the edge's outward normal n = (0,-1,-1) up, the left is
        // n x (+x) = (0,-1,1): towards +z, i.e. along the front face (y = 0)
        const std::array<int, 2> forward{front, bottom};
        const std::array<int, 2> expected = c.vertices[0] == 0 ? forward : std::array<int, 2>{bottom, front};
        EXPECT_EQ(c.sides, expected);
    }
}

TEST(GeometryFeatures, TurnAngleMakesCorners) {
    // the 24-gon rims turn by 15 degrees: corners everywhere iff the turn limit is below
    FeatureOptions tight;
    tight.turn_degrees = 10;
    const FeatureSet f = detect_features(ngon_prism(24), tight);
    EXPECT_EQ(f.corners.size(), 48u);
    EXPECT_EQ(f.curves.size(), 48u);
    // the feature angle decides the sides: above 15 degrees, sharp
    FeatureOptions low;
    low.angle_degrees = 10;
    EXPECT_EQ(detect_features(ngon_prism(24), low).edges.size(), 72u);
}

TEST(GeometryFeatures, ChainsShorterThanTheMinimumAreDroppedWhole) {
    // the unit cube (one chain of 12 edges, length 12) and a cube of edge 0.1 beside it
    // (length 1.2): a minimum of 5 keeps the big cube's every edge and none of the small's
    TriangleSurface s = unit_cube_surface();
    const TriangleSurface small = unit_cube_surface();
    const int offset = static_cast<int>(s.vertices.size());
    for (const auto& v : small.vertices) s.vertices.push_back(0.1 * v + Eigen::Vector3d(3, 0, 0));
    for (const auto& t : small.triangles) s.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    EXPECT_EQ(detect_features(s).curves.size(), 24u);
    FeatureOptions options;
    options.min_chain_length = 5;
    const FeatureSet f = detect_features(s, options);
    EXPECT_EQ(f.edges.size(), 12u);
    EXPECT_EQ(f.corners.size(), 8u);
    EXPECT_EQ(f.curves.size(), 12u);
    for (const auto& e : f.edges) EXPECT_LT(e[1], offset);
    EXPECT_EQ(f.patches, 7);  // the big cube's 6 faces, the small cube one patch
    options.min_chain_length = 12.5;  // above the big cube's chain too: no features at all
    const FeatureSet none = detect_features(s, options);
    EXPECT_TRUE(none.edges.empty());
    EXPECT_TRUE(none.curves.empty());
    EXPECT_EQ(none.patches, 2);
    options.min_chain_length = -1;
    EXPECT_THROW((void)detect_features(s, options), std::invalid_argument);
}

TEST(GeometryFeatures, RefusesBadInput) {
    TriangleSurface open = unit_cube_surface();
    open.triangles.pop_back();
    EXPECT_THROW((void)detect_features(open), std::invalid_argument);
    FeatureOptions bad;
    bad.angle_degrees = 0;
    EXPECT_THROW((void)detect_features(unit_cube_surface(), bad), std::invalid_argument);
    bad.angle_degrees = 180;
    EXPECT_THROW((void)detect_features(unit_cube_surface(), bad), std::invalid_argument);
    bad.angle_degrees = std::nan("");
    EXPECT_THROW((void)detect_features(unit_cube_surface(), bad), std::invalid_argument);
    bad = {};
    bad.turn_degrees = -1;
    EXPECT_THROW((void)detect_features(unit_cube_surface(), bad), std::invalid_argument);
}

TEST(GeometryFeatures, SplitEdgeStaysOneCurve) {
    // the cube with edge 0-1 split at its midpoint (both faces along it re-fanned)
    TriangleSurface s = unit_cube_surface();
    s.vertices.emplace_back(0.5, 0.0, 0.0);  // 8: midpoint of edge 0-1 (bottom, y = 0)
    // bottom face {0,2,1},{1,2,3} -> {0,2,8},{8,2,1},{1,2,3}; front face {0,1,4},{1,5,4} -> {0,8,4},{8,1,4},{1,5,4}
    s.triangles[0] = {0, 2, 8};
    s.triangles.push_back({8, 2, 1});
    s.triangles[4] = {0, 8, 4};
    s.triangles.push_back({8, 1, 4});
    const FeatureSet f = detect_features(s);
    EXPECT_EQ(f.edges.size(), 13u);  // edge 0-1 now two feature edges
    EXPECT_EQ(f.corners.size(), 8u);  // 8 is a straight 2-edge vertex
    ASSERT_EQ(f.curves.size(), 12u);
    std::size_t three = 0;
    for (const auto& c : f.curves) three += c.vertices.size() == 3 && c.vertices[1] == 8 ? 1 : 0;
    EXPECT_EQ(three, 1u);
}

TEST(GeometryFeatures, PolylineHelpers) {
    const std::vector<Eigen::Vector3d> l{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    const PolylinePoint p = closest_on_polyline(l, false, Eigen::Vector3d(1.5, 0.5, 2));
    EXPECT_NEAR(p.arc, 1.5, 1e-12);
    EXPECT_NEAR(p.distance, std::sqrt(0.25 + 4), 1e-12);
    EXPECT_TRUE(p.point.isApprox(Eigen::Vector3d(1, 0.5, 0)));
    // closed: the segment back to the start counts
    EXPECT_NEAR(closest_on_polyline(l, false, Eigen::Vector3d(0.4, 0.6, 0)).distance, 0.6, 1e-12);
    EXPECT_NEAR(closest_on_polyline(l, true, Eigen::Vector3d(0.4, 0.6, 0)).distance, 0.2 / std::sqrt(2.0), 1e-12);
    EXPECT_TRUE(point_at_arc(l, false, 1.25).isApprox(Eigen::Vector3d(1, 0.25, 0)));
    EXPECT_TRUE(point_at_arc(l, false, 10).isApprox(Eigen::Vector3d(1, 1, 0)));
    EXPECT_TRUE(point_at_arc(l, false, -1).isApprox(Eigen::Vector3d(0, 0, 0)));
}

}  // namespace

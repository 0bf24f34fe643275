// AABB tree queries against brute force, triangle/box overlap, ray casts, and the inside
// test against known points (cube, sphere) and against the exact winding number on every
// shared model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <limits>
#include <numbers>
#include <random>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/inside.hpp"
#include "dualhex/geometry/triangle_geometry.hpp"
#include "test_geometry_fixture.hpp"

using namespace dualhex::geometry;
using namespace geometry_test;
using Eigen::AlignedBox3d;
using Eigen::Vector3d;

namespace {

/// A subdivided icosahedron projected onto the sphere of radius r about c.
TriangleSurface icosphere(int subdivisions, double r = 1.0, Vector3d c = Vector3d::Zero()) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    TriangleSurface s;
    for (const auto& p : {Vector3d(-1, t, 0), Vector3d(1, t, 0), Vector3d(-1, -t, 0), Vector3d(1, -t, 0),
                          Vector3d(0, -1, t), Vector3d(0, 1, t), Vector3d(0, -1, -t), Vector3d(0, 1, -t),
                          Vector3d(t, 0, -1), Vector3d(t, 0, 1), Vector3d(-t, 0, -1), Vector3d(-t, 0, 1)})
        s.vertices.push_back(p.normalized());
    s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<int, int>, int> mid;
        auto midpoint = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            auto [it, fresh] = mid.try_emplace({key.first, key.second}, static_cast<int>(s.vertices.size()));
            if (fresh) s.vertices.push_back((s.vertices[a] + s.vertices[b]).normalized());
            return it->second;
        };
        std::vector<std::array<int, 3>> next;
        for (const auto& tri : s.triangles) {
            const int ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]), ca = midpoint(tri[2], tri[0]);
            next.push_back({tri[0], ab, ca});
            next.push_back({tri[1], bc, ab});
            next.push_back({tri[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        s.triangles = std::move(next);
    }
    for (auto& p : s.vertices) p = c + r * p;
    return s;
}

double brute_squared_distance(const TriangleSurface& s, const Vector3d& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : s.triangles)
        best = std::min(best, (closest_point_on_triangle(p, s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]) - p)
                                  .squaredNorm());
    return best;
}

TEST(TriangleGeometry, ClosestPointRegions) {
    const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_TRUE(closest_point_on_triangle({0.2, 0.2, 5}, a, b, c).isApprox(Vector3d(0.2, 0.2, 0)));
    EXPECT_TRUE(closest_point_on_triangle({-1, -1, 0}, a, b, c).isApprox(a));
    EXPECT_TRUE(closest_point_on_triangle({2, -1, 0}, a, b, c).isApprox(b));
    EXPECT_TRUE(closest_point_on_triangle({0.5, -3, 1}, a, b, c).isApprox(Vector3d(0.5, 0, 0)));
    EXPECT_TRUE(closest_point_on_triangle({1, 1, 0}, a, b, c).isApprox(Vector3d(0.5, 0.5, 0)));
}

TEST(TriangleGeometry, TriangleBoxOverlap) {
    const AlignedBox3d box(Vector3d(0, 0, 0), Vector3d(1, 1, 1));
    EXPECT_TRUE(triangle_box_overlap(box, {0.5, 0.5, 0.5}, {5, 0.5, 0.5}, {0.5, 5, 0.5}));   // corner inside
    EXPECT_TRUE(triangle_box_overlap(box, {-5, -5, 0.5}, {5, -5, 0.5}, {0, 10, 0.5}));      // cuts through
    EXPECT_FALSE(triangle_box_overlap(box, {2, 2, 2}, {3, 2, 2}, {2, 3, 2}));                // far away
    // Bounding boxes overlap but the plane x+y+z = 3.5 misses the box (touches at 3).
    EXPECT_FALSE(triangle_box_overlap(box, {3.5, 0, 0}, {0, 3.5, 0}, {0, 0, 3.5}));
    EXPECT_TRUE(triangle_box_overlap(box, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}));  // touches corner (1,1,1)
    // Only an edge cross-product axis separates: all three corners have x + y >= 2.05 > 2
    // (the box's maximum), while the box axes and the triangle's plane do not separate.
    EXPECT_FALSE(triangle_box_overlap(box, {1.35, 0.7, -1}, {0.7, 1.35, 2}, {3, 3, 0.5}));
    EXPECT_TRUE(triangle_box_overlap(box, {1.2, 0.6, -1}, {0.6, 1.2, 2}, {3, 3, 0.5}));  // x + y = 1.8
}

TEST(AabbTree, MatchesBruteForceOnSharedModel) {
    const auto s = read_surface(shared_surface("cgal_elephant.off"));
    const AabbTree tree(s);
    std::mt19937 rng(7);
    const AlignedBox3d bb = tree.bounds();
    const Vector3d lo = bb.min() - 0.2 * bb.sizes(), size = 1.4 * bb.sizes();
    std::uniform_real_distribution<double> u(0, 1);
    for (int n = 0; n < 200; ++n) {
        const Vector3d p = lo + Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(size);
        const auto cp = tree.closest_point(p);
        EXPECT_NEAR(cp.squared_distance, brute_squared_distance(s, p), 1e-12);
        EXPECT_NEAR((cp.point - p).squaredNorm(), cp.squared_distance, 1e-12);
    }
    for (int n = 0; n < 100; ++n) {
        const Vector3d c = lo + Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(size);
        const AlignedBox3d box(c, c + 0.05 * bb.sizes().maxCoeff() * Vector3d::Ones());
        std::vector<int> brute;
        for (std::size_t t = 0; t < s.triangles.size(); ++t) {
            const auto& tri = s.triangles[t];
            if (triangle_box_overlap(box, s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]]))
                brute.push_back(static_cast<int>(t));
        }
        auto got = tree.triangles_in_box(box);
        std::sort(got.begin(), got.end());
        EXPECT_EQ(got, brute);
        EXPECT_EQ(tree.intersects_box(box), !brute.empty());
    }
}

TEST(AabbTree, CubeQueriesAndRays) {
    const AabbTree tree(unit_cube_surface());
    const auto cp = tree.closest_point({0.5, 0.5, 2.0});
    EXPECT_NEAR(cp.squared_distance, 1.0, 1e-15);
    EXPECT_TRUE(cp.point.isApprox(Vector3d(0.5, 0.5, 1.0)));
    EXPECT_NEAR(tree.squared_distance({0.5, 0.5, 0.6}), 0.16, 1e-15);  // inside: to the top face
    // A bounded query: the same answer below the bound, "none" (the bound, no triangle) above.
    const auto near = tree.closest_point({0.5, 0.5, 2.0}, 1.5);
    EXPECT_NEAR(near.squared_distance, 1.0, 1e-15);
    EXPECT_GE(near.triangle, 0);
    const auto none = tree.closest_point({0.5, 0.5, 2.0}, 0.5);
    EXPECT_EQ(none.squared_distance, 0.5);
    EXPECT_EQ(none.triangle, -1);
    EXPECT_FALSE(tree.intersects_box(AlignedBox3d(Vector3d::Constant(0.2), Vector3d::Constant(0.8))));
    EXPECT_TRUE(tree.intersects_box(AlignedBox3d(Vector3d::Constant(0.8), Vector3d::Constant(1.2))));
    const Vector3d dir = Vector3d(1, 0.1, 0.05).normalized();
    const auto hit = tree.first_hit({0.5, 0.5, 0.5}, dir);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->point.x(), 1.0, 1e-12);
    EXPECT_EQ(tree.all_hits({-1, 0.3, 0.4}, Vector3d(1, 0.05, 0.02).normalized()).size(), 2u);
    EXPECT_TRUE(tree.all_hits({-1, 0.3, 0.4}, Vector3d(-1, 0.05, 0.02).normalized()).empty());
}

TEST(Inside, CubeKnownPoints) {
    const auto cube = unit_cube_surface();
    const AabbTree tree(cube);
    for (const Vector3d& p : {Vector3d(0.5, 0.5, 0.5), Vector3d(0.01, 0.99, 0.5), Vector3d(0.5, 0.5, 0.999),
                              Vector3d(0.25, 0.5, 0.5) /* on the plane of a diagonal */}) {
        EXPECT_TRUE(is_inside(tree, p)) << p.transpose();
        EXPECT_NEAR(winding_number(cube, p), 1.0, 1e-9);
    }
    for (const Vector3d& p : {Vector3d(1.5, 0.5, 0.5), Vector3d(-0.01, 0.5, 0.5), Vector3d(0.5, 0.5, 1.001),
                              Vector3d(2, 2, 2), Vector3d(0.5, 0.5, -3)}) {
        EXPECT_FALSE(is_inside(tree, p)) << p.transpose();
        EXPECT_NEAR(winding_number(cube, p), 0.0, 1e-9);
    }
    // Rays from the centre along the face diagonals pass through cube edges and vertices:
    // the majority vote still says inside.
    EXPECT_GE(inside_votes(tree, {0.5, 0.5, 0.5}), 3);
}

TEST(Inside, SphereKnownPoints) {
    const auto sphere = icosphere(3, 2.0, Vector3d(1, -1, 0.5));
    EXPECT_TRUE(check_edges(sphere).closed());
    const AabbTree tree(sphere);
    std::mt19937 rng(11);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> u(0, 1);
    for (int n = 0; n < 500; ++n) {
        const Vector3d d = Vector3d(g(rng), g(rng), g(rng)).normalized();
        const double r_in = 2.0 * 0.97 * std::cbrt(u(rng));  // inscribed radius of the polyhedron > 0.98 * 2
        const double r_out = 2.0 * (1.001 + u(rng));
        EXPECT_TRUE(is_inside(tree, Vector3d(1, -1, 0.5) + r_in * d));
        EXPECT_FALSE(is_inside(tree, Vector3d(1, -1, 0.5) + r_out * d));
    }
}

class InsideShared : public ::testing::TestWithParam<const char*> {};

TEST_P(InsideShared, AgreesWithWindingNumber) {
    const auto s = read_surface(shared_surface(GetParam()));
    const AabbTree tree(s);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    const AlignedBox3d bb = tree.bounds();
    const double diag = bb.diagonal().norm();
    int inside = 0, checked = 0;
    for (int n = 0; n < 150; ++n) {
        const Vector3d p = bb.min() - 0.05 * bb.sizes() + 1.1 * Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(bb.sizes());
        if (tree.squared_distance(p) < 1e-12 * diag * diag) continue;  // on the surface: undecided
        const double w = winding_number(s, p);
        ASSERT_LT(std::abs(w - std::round(w)), 1e-6) << p.transpose();
        EXPECT_EQ(is_inside(tree, p), std::round(w) == 1.0) << GetParam() << " at " << p.transpose() << " w=" << w;
        inside += std::round(w) == 1.0;
        ++checked;
    }
    EXPECT_GT(checked, 140);
    EXPECT_GT(inside, 0);
}

INSTANTIATE_TEST_SUITE_P(Data, InsideShared,
                         ::testing::Values("cgal_cube.off", "cgal_joint.off", "cgal_anchor.off", "cgal_elephant.off",
                                           "cgal_fandisk.off", "cgal_armadillo.off", "gmsh_lever.stl",
                                           "tue_fandisk.stl", "tue_block.stl", "tue_B0.stl", "tue_B13.stl",
                                           "gao_bone_tri.off", "gao_bunny_tri.off", "gao_kitten_tri.off",
                                           "gao_eight_tri.off"),
                         [](const auto& info) {
                             std::string n = info.param;
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

}  // namespace

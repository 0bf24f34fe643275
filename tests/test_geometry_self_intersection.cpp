// The exact self-intersection check: hand-made cases at the exact boundary (touching at a
// point, one double step apart, coplanar folds), whole surfaces that are and are not
// embedded, and triangles_intersect against an independent oracle (a separating-axis test
// in exact integer arithmetic) on random small-integer triangles, where touching and
// coplanar cases are frequent.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <random>

#include "dualhex/geometry/self_intersection.hpp"
#include "test_geometry_fixture.hpp"

using namespace dualhex::geometry;
using namespace geometry_test;
using Eigen::Vector3d;
using Tri = std::array<Vector3d, 3>;

namespace {

const Tri kBase{Vector3d(0, 0, 0), Vector3d(4, 0, 0), Vector3d(0, 4, 0)};

TEST(TrianglesIntersect, ExactAtTheBoundary) {
    // A vertical triangle whose lowest corner is at height h above the base's interior.
    auto standing = [](double h) { return Tri{Vector3d(1, 1, h), Vector3d(1, 1, h + 1), Vector3d(2, 1, h + 1)}; };
    EXPECT_TRUE(triangles_intersect(kBase, standing(0)));       // touches at one point
    EXPECT_TRUE(triangles_intersect(kBase, standing(-0.5)));    // pierces
    EXPECT_FALSE(triangles_intersect(kBase, standing(std::nextafter(0.0, 1.0))));  // 2^-1074 above: apart
    EXPECT_FALSE(triangles_intersect(kBase, standing(1e-300)));
    // Touching the base's edge x + y = 4 exactly at (2, 2, 0), and missing it by one ulp.
    EXPECT_TRUE(triangles_intersect(kBase, Tri{Vector3d(2, 2, 0), Vector3d(3, 3, 1), Vector3d(3, 3, -1)}));
    const double past = std::nextafter(2.0, 3.0);
    EXPECT_FALSE(triangles_intersect(kBase, Tri{Vector3d(past, 2, 0), Vector3d(3, 3, 1), Vector3d(3, 3, -1)}));
    // Coplanar: overlapping, contained, touching at a vertex, disjoint.
    EXPECT_TRUE(triangles_intersect(kBase, Tri{Vector3d(1, 1, 0), Vector3d(5, 1, 0), Vector3d(1, 5, 0)}));
    EXPECT_TRUE(triangles_intersect(kBase, Tri{Vector3d(1, 1, 0), Vector3d(1.5, 1, 0), Vector3d(1, 1.5, 0)}));
    EXPECT_TRUE(triangles_intersect(kBase, Tri{Vector3d(4, 0, 0), Vector3d(5, 0, 0), Vector3d(5, 1, 0)}));
    EXPECT_FALSE(triangles_intersect(kBase, Tri{Vector3d(past, past, 0), Vector3d(5, 3, 0), Vector3d(3, 5, 0)}));
    // Parallel planes.
    EXPECT_FALSE(triangles_intersect(kBase, Tri{Vector3d(0, 0, 1), Vector3d(4, 0, 1), Vector3d(0, 4, 1)}));
}

// Independent oracle: closed convex sets are disjoint iff some axis separates them; for two
// triangles the normals, the edge-edge cross products and the in-plane edge normals suffice.
using I3 = std::array<long long, 3>;
I3 sub(const I3& a, const I3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
I3 cross(const I3& a, const I3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
long long dot(const I3& a, const I3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

bool oracle_intersect(const std::array<I3, 3>& a, const std::array<I3, 3>& b) {
    std::vector<I3> axes;
    const I3 na = cross(sub(a[1], a[0]), sub(a[2], a[0])), nb = cross(sub(b[1], b[0]), sub(b[2], b[0]));
    axes.push_back(na);
    axes.push_back(nb);
    for (int i = 0; i < 3; ++i) {
        const I3 ea = sub(a[(i + 1) % 3], a[i]), eb = sub(b[(i + 1) % 3], b[i]);
        axes.push_back(cross(na, ea));
        axes.push_back(cross(nb, eb));
        for (int j = 0; j < 3; ++j) axes.push_back(cross(ea, sub(b[(j + 1) % 3], b[j])));
    }
    for (const I3& axis : axes) {
        long long amin = LLONG_MAX, amax = LLONG_MIN, bmin = LLONG_MAX, bmax = LLONG_MIN;
        for (const I3& p : a) amin = std::min(amin, dot(axis, p)), amax = std::max(amax, dot(axis, p));
        for (const I3& p : b) bmin = std::min(bmin, dot(axis, p)), bmax = std::max(bmax, dot(axis, p));
        if (amax < bmin || bmax < amin) return false;
    }
    return true;
}

bool degenerate(const std::array<I3, 3>& t) { return cross(sub(t[1], t[0]), sub(t[2], t[0])) == I3{0, 0, 0}; }

TEST(TrianglesIntersect, AgreesWithAnExactSeparatingAxisOracle) {
    std::mt19937 rng(15);
    std::uniform_int_distribution<int> coord(-2, 2);
    auto random_tri = [&] {
        std::array<I3, 3> t;
        do {
            for (auto& p : t)
                for (auto& x : p) x = coord(rng);
        } while (degenerate(t));
        return t;
    };
    // Exact transforms that must not change the answer: 2^-60 scaling and an integer shift.
    auto as_doubles = [](const std::array<I3, 3>& t, double scale, const Vector3d& shift) {
        Tri out;
        for (int c = 0; c < 3; ++c)
            out[c] = Vector3d(t[c][0], t[c][1], t[c][2]) * scale + shift;
        return out;
    };
    const Vector3d shift(1e6, -3e5, 7);
    int hits = 0;
    for (int n = 0; n < 20000; ++n) {
        const auto a = random_tri(), b = random_tri();
        const bool expected = oracle_intersect(a, b);
        hits += expected ? 1 : 0;
        const Tri da = as_doubles(a, 1, Vector3d::Zero()), db = as_doubles(b, 1, Vector3d::Zero());
        ASSERT_EQ(triangles_intersect(da, db), expected) << n;
        ASSERT_EQ(triangles_intersect(db, da), expected) << n;
        ASSERT_EQ(triangles_intersect(Tri{da[1], da[2], da[0]}, Tri{db[0], db[2], db[1]}), expected) << n;
        ASSERT_EQ(triangles_intersect(as_doubles(a, std::ldexp(1.0, -60), Vector3d::Zero()),
                                      as_doubles(b, std::ldexp(1.0, -60), Vector3d::Zero())),
                  expected) << n;
        ASSERT_EQ(triangles_intersect(as_doubles(a, 1, shift), as_doubles(b, 1, shift)), expected) << n;
    }
    // Both answers occur often: the comparison is not vacuous.
    EXPECT_GT(hits, 2000);
    EXPECT_LT(hits, 18000);
}

TriangleSurface two_cubes(double offset) {
    TriangleSurface s = unit_cube_surface();
    const TriangleSurface c = unit_cube_surface(offset, offset + 1);
    for (const auto& p : c.vertices) s.vertices.push_back(p);
    for (const auto& t : c.triangles) s.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    return s;
}

TEST(SelfIntersections, SurfacesThatAreAndAreNotEmbedded) {
    EXPECT_TRUE(find_self_intersections(unit_cube_surface()).empty());
    EXPECT_TRUE(find_self_intersections(two_cubes(1.5)).empty());
    const auto overlap = find_self_intersections(two_cubes(0.5));
    EXPECT_GT(overlap.pair_count, 0u);
    for (const auto& p : overlap.pairs) {  // each pair has one triangle of each cube
        EXPECT_LT(p[0], 12);
        EXPECT_GE(p[1], 12);
    }
    // Touching along a face (other vertex ids): not embedded either.
    EXPECT_GT(find_self_intersections(two_cubes(1.0)).pair_count, 0u);
    // A cube with corner 7 pushed through the opposite corner region.
    TriangleSurface dent = unit_cube_surface();
    dent.vertices[7] = Vector3d(-0.5, -0.5, -0.5);
    EXPECT_GT(find_self_intersections(dent).pair_count, 0u);
}

TEST(SelfIntersections, AdjacentTrianglesMayShareOnlyWhatTheirIndicesShare) {
    TriangleSurface s;
    s.vertices = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(1, 1, 0), Vector3d(0.5, 2, 0),
                  Vector3d(0, 0, 1)};
    auto pairs = [&](std::vector<std::array<int, 3>> t) {
        s.triangles = std::move(t);
        return find_self_intersections(s).pair_count;
    };
    EXPECT_EQ(pairs({{0, 1, 2}, {1, 3, 2}}), 0u);  // common edge, opposite sides
    EXPECT_EQ(pairs({{0, 1, 2}, {0, 1, 3}}), 1u);  // common edge, same side, coplanar: folded
    EXPECT_EQ(pairs({{0, 1, 2}, {0, 1, 5}}), 0u);  // common edge, not coplanar
    EXPECT_EQ(pairs({{0, 1, 2}, {0, 3, 4}}), 1u);  // common vertex, coplanar wedges overlap
    EXPECT_EQ(pairs({{0, 1, 5}, {0, 2, 5}}), 0u);  // common edge 0-5 in different planes
    EXPECT_EQ(pairs({{0, 1, 2}, {2, 1, 0}}), 1u);  // the same three vertices
    s.vertices.push_back(Vector3d(2, 0, 0));       // 6: collinear with 0 and 1
    s.triangles = {{0, 1, 6}, {0, 1, 2}};
    const auto found = find_self_intersections(s);
    EXPECT_EQ(found.degenerate_count, 1u);
    ASSERT_EQ(found.degenerate.size(), 1u);
    EXPECT_EQ(found.degenerate[0], 0);
    EXPECT_NE(found.describe(s).find("1 degenerate triangle"), std::string::npos);
}

TEST(SelfIntersections, GivesUpRatherThanGoQuadratic) {
    // A closed cone over a 400-gon: every side triangle's box holds the apex, so all 400
    // overlap each other (160,000 candidate pairs); embedded all the same.
    TriangleSurface cone;
    const int n = 400;
    cone.vertices.emplace_back(0, 0, 1);  // apex
    cone.vertices.emplace_back(0, 0, 0);  // base centre
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        cone.vertices.emplace_back(std::cos(a), std::sin(a), 0);
    }
    for (int i = 0; i < n; ++i) {
        const int p = 2 + i, q = 2 + (i + 1) % n;
        cone.triangles.push_back({0, p, q});
        cone.triangles.push_back({1, q, p});
    }
    const auto full = find_self_intersections(cone);
    EXPECT_TRUE(full.empty());
    EXPECT_FALSE(full.gave_up);
    const auto capped = find_self_intersections(cone, 5, 1000, 50'000);
    EXPECT_TRUE(capped.gave_up);
    EXPECT_FALSE(capped.empty());  // not decided is not "embedded"
    EXPECT_NE(capped.describe(cone).find("gave up"), std::string::npos);
}

TEST(SelfIntersections, ReadSurfaceRefusesNamingTheFileAndPairs) {
    TempDir dir;
    const auto path = write_text(dir.file("overlap.off"), off_text(two_cubes(0.5)));
    try {
        (void)read_surface(path);
        ADD_FAILURE() << "accepted";
    } catch (const SurfaceError& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind(path + ": surface is not embedded: ", 0), 0u) << msg;
        EXPECT_NE(msg.find("pairs of intersecting triangles, e.g. "), std::string::npos) << msg;
    }
    EXPECT_EQ(read_surface(path, {.reject_self_intersections = false}).triangles.size(), 24u);
    // A flat closed surface (zero volume): two triangles back to back.
    const auto flat = write_text(dir.file("flat.off"), "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n");
    try {
        (void)read_surface(flat);
        ADD_FAILURE() << "accepted";
    } catch (const SurfaceError& e) {
        EXPECT_NE(std::string(e.what()).find("not embedded"), std::string::npos) << e.what();
    }
}

}  // namespace

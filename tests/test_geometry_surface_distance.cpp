// Two-sided hex-boundary / surface distance (surface_distance.hpp): zero for a hex mesh
// of the surface's solid, the shift for a shifted one (with the mean computed by hand),
// and a case the old one-sided measure misses entirely.
#include <gtest/gtest.h>

#include <cmath>

#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/surface_distance.hpp"
#include "test_geometry_fixture.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex::geometry;
using namespace geometry_test;
using Eigen::Vector3d;

TEST(SurfaceDistance, CubeMeshOfTheCubeIsAtZero) {
    const AabbTree cube(unit_cube_surface());
    const auto d = surface_distance(hex_block(2, 2, 2, 0.5).mesh, cube);
    EXPECT_NEAR(d.diagonal, std::sqrt(3.0), 1e-15);
    EXPECT_LT(d.mesh_to_surface.max, 1e-12);
    EXPECT_LT(d.surface_to_mesh.max, 1e-12);
    EXPECT_LT(d.mean(), 1e-12);
    EXPECT_EQ(d.boundary_vertices, 26u);
    EXPECT_EQ(d.share_vertices_on_surface, 1.0);
    EXPECT_GT(d.mesh_to_surface.samples, 24u * 100);  // dense, not just vertices
    EXPECT_GT(d.surface_to_mesh.samples, 12u * 100);
}

TEST(SurfaceDistance, ShiftedCubeIsAtTheShift) {
    const AabbTree cube(unit_cube_surface());
    const auto d = surface_distance(hex_block(2, 2, 2, 0.5, Vector3d(0.1, 0, 0)).mesh, cube);
    EXPECT_NEAR(d.mesh_to_surface.max, 0.1, 1e-12);
    EXPECT_NEAR(d.surface_to_mesh.max, 0.1, 1e-12);
    EXPECT_NEAR(d.relative(d.max()), 0.1 / std::sqrt(3.0), 1e-12);
    // Mean from the shifted boundary, by hand: face x = 1.1 at 0.1; the four side faces
    // at 0 except x in (1, 1.1] (mean 0.005 each); face x = 0.1 at min(0.1, distance to
    // the square's edge), mean (1 - 0.8^3) / 6. The surface side is the mirror image.
    const double expected = (0.1 + 4 * 0.005 + (1 - 0.512) / 6) / 6;
    EXPECT_NEAR(d.mesh_to_surface.mean, expected, 1e-3);
    EXPECT_NEAR(d.surface_to_mesh.mean, expected, 1e-3);
    // 26 boundary vertices; off the surface: the 9 at x = 1.1 and the centre of x = 0.1.
    EXPECT_EQ(d.boundary_vertices, 26u);
    EXPECT_DOUBLE_EQ(d.share_vertices_on_surface, 16.0 / 26.0);
}

TEST(SurfaceDistance, HalfCoveredSurfaceIsFarOnlyTwoSided) {
    TriangleSurface two = unit_cube_surface();
    const TriangleSurface other = unit_cube_surface(3, 4);
    for (const auto& p : other.vertices) two.vertices.push_back(p);
    for (const auto& t : other.triangles) two.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    const AabbTree tree(two);
    const HexMesh mesh = hex_block(2, 2, 2, 0.5).mesh;             // only the first cube
    EXPECT_EQ(boundary_to_surface_distance(mesh, tree).max, 0.0);  // the one-sided report sees nothing
    const auto d = surface_distance(mesh, tree);
    EXPECT_LT(d.mesh_to_surface.max, 1e-12);
    // the corner (4, 4, 4) of the second cube, from (1, 1, 1)
    EXPECT_NEAR(d.surface_to_mesh.max, 3 * std::sqrt(3.0), 1e-12);
    EXPECT_EQ(d.surface_to_mesh.farthest, Vector3d(4, 4, 4));
    EXPECT_GT(d.surface_to_mesh.mean, 1.0);
}

TEST(SurfaceDistance, BadInputIsRefused) {
    const AabbTree cube(unit_cube_surface());
    EXPECT_THROW((void)surface_distance(HexMesh{}, cube), std::invalid_argument);
    SurfaceDistanceOptions bad;
    bad.sample_spacing = 0;
    EXPECT_THROW((void)surface_distance(hex_block(1, 1, 1).mesh, cube, bad), std::invalid_argument);
    HexMesh broken = hex_block(1, 1, 1).mesh;
    broken.hexes[0][0] = 8;
    EXPECT_THROW((void)surface_distance(broken, cube), std::invalid_argument);
}

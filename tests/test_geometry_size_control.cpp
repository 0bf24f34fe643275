// Size control of the surface octree and of `dualhex mesh`: crossing cells refined to the
// target size and no further, max depth only a cap, the band, curvature refining a sphere
// and not a flat face, the leaf bound refusing before the work, the mesh of a cube having
// boundary hexes of about the target size, and the CLI refusing bad size options (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/surface_curvature.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "run_process.hpp"
#include "test_geometry_fixture.hpp"

using namespace dualhex;
using namespace dualhex::geometry;
using namespace geometry_test;
using Eigen::Vector3d;

namespace {

/// A UV sphere of radius r around the origin, outward triangles.
TriangleSurface sphere_surface(double r, int rings = 24, int segments = 48) {
    TriangleSurface s;
    s.vertices.emplace_back(0, 0, r);  // north pole 0
    for (int i = 1; i < rings; ++i) {
        const double theta = std::numbers::pi * i / rings;
        for (int j = 0; j < segments; ++j) {
            const double phi = 2 * std::numbers::pi * j / segments;
            s.vertices.emplace_back(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                                    r * std::cos(theta));
        }
    }
    const int south = static_cast<int>(s.vertices.size());
    s.vertices.emplace_back(0, 0, -r);
    auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
    for (int j = 0; j < segments; ++j) {
        s.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
        s.triangles.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
        for (int i = 1; i + 1 < rings; ++i) {
            s.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            s.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
    }
    return s;
}

SurfaceOctreeOptions size_only(double size, int max_depth = 8) {
    SurfaceOctreeOptions o;
    o.surface_size = size;
    o.max_depth = max_depth;
    o.thickness_factor = 0;
    o.curvature_angle = 0;
    return o;
}

/// Distance between two boxes (0 if they overlap).
double box_distance(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
    const Vector3d gap = (a.min() - b.max()).cwiseMax(b.min() - a.max()).cwiseMax(0.0);
    return gap.norm();
}

TEST(SizeControl, NormalSpreadOfFlatFoldedAndOppositeSheets) {
    const TriangleSurface cube = unit_cube_surface();
    const auto normals = area_normals(cube);
    EXPECT_DOUBLE_EQ(normal_spread({0, 1}, normals), 0.0);                      // one face (z = 0)
    EXPECT_NEAR(normal_spread({0, 1, 4, 5}, normals), std::numbers::pi / 4, 1e-12);  // z = 0 and y = 0: an edge
    EXPECT_DOUBLE_EQ(normal_spread({0, 1, 2, 3}, normals), std::numbers::pi);  // z = 0 and z = 1: opposite
    EXPECT_NEAR(surface_area(cube), 6.0, 1e-12);
}

TEST(SizeControl, CrossingCellsReachTheTargetSizeAndNoFurther) {
    const AabbTree tree(read_surface(shared_surface("cgal_cube.off")));  // edge 2, root 2.4
    const double size = 0.2;
    const SurfaceOctree oct = surface_octree(tree, size_only(size));
    EXPECT_EQ(oct.size_level, 4);  // 2.4 / 16 = 0.15 <= 0.2 < 0.3
    EXPECT_EQ(oct.size_level, level_for_size(oct.root, size));
    std::size_t crossing = 0;
    for (const Leaf& l : oct.grid.leaves()) {
        if (!surface_crosses(tree, oct.root, l)) {
            EXPECT_LE(l.level, 4) << to_string(l);
            continue;
        }
        ++crossing;
        EXPECT_LE(oct.root.edge(l.level), size) << to_string(l);
        EXPECT_GT(oct.root.edge(l.level), size / 2) << to_string(l);  // minimal
    }
    EXPECT_EQ(crossing, oct.crossing_leaves);
    EXPECT_GT(crossing, 0u);
}

TEST(SizeControl, MaxDepthIsOnlyACap) {
    const AabbTree tree(read_surface(shared_surface("cgal_cube.off")));
    const SurfaceOctree capped = surface_octree(tree, size_only(0.01, 3));  // needs level 8
    EXPECT_EQ(capped.size_level, 8);
    EXPECT_EQ(capped.grid.max_level(), 3);
    for (const Leaf& l : capped.grid.leaves())
        if (surface_crosses(tree, capped.root, l)) {
            EXPECT_EQ(l.level, 3) << to_string(l);
        }
    // A larger cap than the size needs changes nothing: the size stops the refinement.
    const SurfaceOctree a = surface_octree(tree, size_only(0.2, 5));
    const SurfaceOctree b = surface_octree(tree, size_only(0.2, 12));
    EXPECT_EQ(a.grid.leaves(), b.grid.leaves());
    EXPECT_EQ(b.grid.max_level(), 4);
}

TEST(SizeControl, BandRefinesCellsNearTheSurface) {
    const AabbTree tree(read_surface(shared_surface("cgal_cube.off")));
    SurfaceOctreeOptions o = size_only(0.2);
    const SurfaceOctree plain = surface_octree(tree, o);
    o.surface_band = 0.35;
    const SurfaceOctree banded = surface_octree(tree, o);
    EXPECT_GT(banded.grid.size(), plain.grid.size());
    const Eigen::AlignedBox3d solid(Vector3d::Constant(-1), Vector3d::Constant(1));
    std::size_t near_not_crossing = 0;
    for (const Leaf& l : banded.grid.leaves()) {
        const Eigen::AlignedBox3d box = banded.root.box(l);
        // Distance to the cube's surface: to the solid from outside, to its boundary from inside.
        const double out = box_distance(box, solid);
        const double in = 1.0 - box.max().cwiseAbs().cwiseMax(box.min().cwiseAbs()).maxCoeff();
        const double d = std::max(out, in);
        if (d <= 0.3) {  // (no cell face lies at 0.35)
            EXPECT_LE(banded.root.edge(l.level), 0.2) << to_string(l);
        }
        if (d > 0 && d <= 0.3) ++near_not_crossing;
    }
    EXPECT_GT(near_not_crossing, 0u);
}

TEST(SizeControl, CurvatureRefinesASphereNotAFlatFace) {
    SurfaceOctreeOptions o = size_only(0.5);
    o.curvature_angle = 10 * std::numbers::pi / 180;
    o.curvature_levels = 2;
    // Sphere of radius 1: root 2.4, size level 3 (0.3); cells of 0.3 see normals turn ~15 deg.
    const AabbTree sphere(sphere_surface(1.0));
    const SurfaceOctree s = surface_octree(sphere, o);
    EXPECT_EQ(s.size_level, 3);
    EXPECT_GT(s.curvature_splits, 0u);
    EXPECT_GE(s.grid.max_level(), 4);
    EXPECT_LE(s.grid.max_level(), 5);  // the cap: size level + 2
    // Box [-1, 1]^3: the same size level; no face cell away from the edges is refined.
    const AabbTree box(unit_cube_surface(-1, 1));
    const SurfaceOctree b = surface_octree(box, o);
    EXPECT_EQ(b.size_level, 3);
    // A leaf below the size level is the child of a split cell: that cell holds an edge of
    // the box (touches two of its face planes), never only a flat face.
    for (const Leaf& l : b.grid.leaves()) {
        if (l.level <= 3) continue;
        const Eigen::AlignedBox3d cell = b.root.box(parent(l));
        int on_face_planes = 0;  // how many of the axes' planes +-1 the closed cell reaches
        for (int a = 0; a < 3; ++a)
            on_face_planes += (cell.min()[a] <= -1 || cell.max()[a] >= 1) ? 1 : 0;
        EXPECT_GE(on_face_planes, 2) << to_string(l);
    }
    EXPECT_GT(b.grid.max_level(), 3);  // edges and corners are refined (normals turn by 90 deg)
    // On the sphere, curvature refines most of the crossing cells.
    std::size_t fine = 0, crossing = 0;
    for (const Leaf& l : s.grid.leaves())
        if (surface_crosses(sphere, s.root, l)) {
            ++crossing;
            fine += l.level > s.size_level ? 1 : 0;
        }
    EXPECT_GT(2 * fine, crossing);
}

TEST(SizeControl, TooFineASizeIsRefusedBeforeTheWork) {
    const AabbTree tree(read_surface(shared_surface("cgal_cube.off")));
    SurfaceOctreeOptions o = size_only(1e-4, 20);
    o.max_leaves = 1'000'000;
    try {
        (void)surface_octree(tree, o);
        FAIL() << "no OctreeTooLarge";
    } catch (const OctreeTooLarge& e) {
        EXPECT_GT(e.leaves(), o.max_leaves);
        EXPECT_NE(std::string(e.what()).find("leaves"), std::string::npos) << e.what();
    }
    // The estimate errs on the large side of the paired grid (the refusal is conservative).
    const SurfaceOctree oct = paired_surface_octree(tree, Balance::Weak, size_only(0.2));
    EXPECT_GE(estimated_leaves(oct.root, surface_area(tree.surface()), 4), oct.grid.size());
}

TEST(SizeControl, RunawayRefinementStopsAtTheLeafBound) {
    // A thin slab: the thickness criterion alone asks for level 10 on both big faces.
    auto slab = unit_cube_surface();
    for (auto& p : slab.vertices) p.z() *= 0.002;
    const AabbTree tree(slab);
    SurfaceOctreeOptions o;
    o.max_depth = 12;
    o.max_leaves = 20'000;
    EXPECT_THROW((void)surface_octree(tree, o), OctreeTooLarge);
}

TEST(SizeControl, ThicknessRefinesAThinSlabUpToItsCap) {
    // A 1 x 1 x 0.01 slab: root 1.2; thickness 0.01 asks for cells of 0.005, level 8.
    auto slab = unit_cube_surface();
    for (auto& p : slab.vertices) p.z() *= 0.01;
    const AabbTree tree(slab);
    SurfaceOctreeOptions o = size_only(0.3, 12);  // size level 2
    o.thickness_factor = 0.5;
    o.thickness_levels = 2;
    const SurfaceOctree capped = surface_octree(tree, o);
    EXPECT_EQ(capped.size_level, 2);
    EXPECT_EQ(capped.grid.max_level(), 4);
    o.thickness_levels = 10;
    EXPECT_EQ(surface_octree(tree, o).grid.max_level(), 8);
}

TEST(SizeControl, NegativeOptionsAreRefused) {
    const AabbTree tree(unit_cube_surface());
    for (auto set : {+[](SurfaceOctreeOptions& o) { o.surface_size = -1; },
                     +[](SurfaceOctreeOptions& o) { o.surface_band = -1; },
                     +[](SurfaceOctreeOptions& o) { o.curvature_angle = -0.1; },
                     +[](SurfaceOctreeOptions& o) { o.curvature_levels = -1; },
                     +[](SurfaceOctreeOptions& o) { o.thickness_levels = -1; }}) {
        SurfaceOctreeOptions o;
        set(o);
        EXPECT_THROW((void)surface_octree(tree, o), std::invalid_argument);
    }
}

// Median edge length of the boundary quads of a mesh.
double median_boundary_edge(const HexMesh& mesh) {
    std::vector<double> lengths;
    for (const auto& q : boundary_quads(mesh))
        for (int e = 0; e < 4; ++e) lengths.push_back((mesh.points[q[e]] - mesh.points[q[(e + 1) % 4]]).norm());
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    return lengths[lengths.size() / 2];
}

mesher::MeshPipelineResult mesh_cube(double size, int max_depth) {
    const AabbTree tree(read_surface(shared_surface("cgal_cube.off")));
    mesher::MeshPipelineOptions o;
    o.size = size;
    o.max_depth = max_depth;
    o.curvature_angle = 0;  // edges and corners would refine further
    return mesher::mesh_surface(tree, o);
}

TEST(SizeControl, CubeMeshHasBoundaryHexesOfTheTargetSize) {
    // Levels 3 and 4 of the root 2.4: edges 0.3 and 0.15.
    const mesher::MeshPipelineResult level3 = mesh_cube(0.31, 8);
    EXPECT_EQ(level3.size_level, 3);
    const double coarse = median_boundary_edge(level3.mesh);
    const double fine = median_boundary_edge(mesh_cube(0.16, 8).mesh);
    // The boundary hexes are the pad's: they span the core's margin to the surface, so
    // they come out up to ~1.3x the cell size; a level off would be 2x.
    EXPECT_NEAR(coarse, 0.3, 0.3 * 0.4);
    EXPECT_NEAR(fine, 0.15, 0.15 * 0.4);
    // A finer size under a low cap stops at the cap: the same mesh as the cap's own size.
    const mesher::MeshPipelineResult capped = mesh_cube(0.01, 4);
    EXPECT_EQ(capped.size_level, 8);
    EXPECT_EQ(capped.octree_depth, 4);
    EXPECT_NEAR(median_boundary_edge(capped.mesh), fine, 1e-9);
}

TEST(SizeControl, MeshesAndVerifiesAtDepth16) {
    // A cube of edge 2 and, 1 above it, a cube of edge 2e-4: root 4.92, so cells of half
    // the small cube's thickness (1e-4) are level 16 (7.5e-5), the cap.
    TriangleSurface s = unit_cube_surface(-1, 1);
    const TriangleSurface tiny = unit_cube_surface(0.9, 0.9002);
    const int offset = static_cast<int>(s.vertices.size());
    for (const auto& p : tiny.vertices) s.vertices.push_back(p + Vector3d(0, 0, 2.1));
    for (const auto& t : tiny.triangles) s.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    const AabbTree tree(s);
    mesher::MeshPipelineOptions o;
    o.size_rel = 0.5;
    o.curvature_angle = 0;
    o.thickness_levels = 16;
    o.max_depth = mesher::kMaxMeshDepth;
    const mesher::MeshPipelineResult r = mesher::mesh_surface(tree, o);  // throws if it does not verify
    EXPECT_EQ(r.octree_depth, 16);
    ASSERT_FALSE(r.mesh.hexes.empty());
    const int finest = *std::max_element(r.cell_data.level.begin(), r.cell_data.level.end());
    EXPECT_EQ(finest, 16);  // hexes inside the tiny cube
    EXPECT_GT(r.quality.min, 0.0);
}

// --- the command line (DUALHEX_EXE) ---

struct CliRun {
    TempDir dir;
    test::ProcessResult operator()(std::vector<std::string> args) {
        args.insert(args.begin(), {"mesh", shared_surface("cgal_cube.off"), "-o", dir.file("out.vtk"), "--force"});
        return test::run_process(DUALHEX_EXE, args, dir.path);
    }
};

TEST(SizeControlCli, BadSizeOptionsExit2WithAMessage) {
    CliRun run;
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--size", "-1"}, "--size"},
        {{"--size", "0"}, "--size"},
        {{"--size-rel", "-0.5"}, "--size-rel"},
        {{"--min-depth", "5", "--max-depth", "4"}, "min depth"},
        {{"--max-depth", "17"}, "max depth"},
        {{"--curvature-angle", "-3"}, "curvature angle"},
        {{"--preset", "huge"}, "--preset"},
        {{"--size", "0.1", "--size-rel", "0.1"}, "--size"},
        {{"--size", "1e-5", "--max-depth", "16"}, "leaves"},
    };
    for (const auto& [args, what] : cases) {
        const test::ProcessResult r = run(args);
        EXPECT_EQ(r.rc, 2) << args[0] << ' ' << args[1] << ": " << r.err;
        EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    }
}

TEST(SizeControlCli, ASizeBelowTheCapWarnsAndMeshesAtTheCap) {
    CliRun run;
    const test::ProcessResult r = run({"--size", "0.01", "--max-depth", "3", "--json"});
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.err.find("warning: size 0.01 needs depth 8, capped at --max-depth 3"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("\"octree_depth\": 3"), std::string::npos) << r.out;
}

}  // namespace

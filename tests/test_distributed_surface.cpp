// dualhex-dist --surface under mpirun -np 1..4: the forest refined by the serial surface
// octree's criterion (geometry::SurfaceRefinement) gives the octree `dualhex mesh` builds
// (same leaf, crossing and curvature counts) and, paired, balanced, installed and
// dualized, the same canonical summary as the serial install of that octree. Bad surfaces,
// bad size options and a leaf budget too small are refused with the serial's exit codes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "dualhex/distributed/canonical_json.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/mesher/mesh_size.hpp"
#include "test_distributed_fixture.hpp"
#include "test_distributed_run.hpp"

namespace dualhex {
namespace {

namespace fs = std::filesystem;

fs::path surface(const char* name) { return fs::path(DUALHEX_SHARED_DATA) / "surfaces" / name; }

struct SerialMesh {
    geometry::SurfaceOctree octree;
    CanonicalSummary summary;
};

// What `dualhex mesh` builds up to its dual: the octree stage, then pair + balance, install.
SerialMesh serial(const fs::path& file, const mesher::MeshSizeOptions& size, Balance b) {
    const geometry::AabbTree tree(geometry::read_surface(file.string()));
    SerialMesh out{geometry::surface_octree(tree, mesher::octree_options(size, tree.bounds())), {}};
    out.summary = test::serial_summary(out.octree.grid, b);
    return out;
}

nlohmann::json dist(int np, const fs::path& file, const std::vector<std::string>& options, const fs::path& scratch) {
    std::vector<std::string> args{"--surface", file.string(), "--json"};
    args.insert(args.end(), options.begin(), options.end());
    const auto r = test::run_dist(np, args, scratch);
    EXPECT_EQ(r.rc, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

void expect_same(const SerialMesh& serial, const nlohmann::json& doc, int np) {
    EXPECT_EQ(doc["ranks"], np);
    EXPECT_EQ(doc["octree"]["leaves"].get<std::size_t>(), serial.octree.grid.size()) << "np " << np;
    EXPECT_EQ(doc["octree"]["crossing_leaves"].get<std::size_t>(), serial.octree.crossing_leaves) << "np " << np;
    EXPECT_EQ(doc["octree"]["curvature_splits"].get<std::size_t>(), serial.octree.curvature_splits) << "np " << np;
    EXPECT_EQ(doc["octree"]["size_level"].get<int>(), serial.octree.size_level);
    EXPECT_EQ(to_json(summary_from_json(doc["summary"])), to_json(serial.summary)) << "np " << np;
    if (np > 1) {  // the refinement itself is spread: every rank decided cells
        for (const auto& r : doc["per_rank"]) EXPECT_GT(r["input"]["decisions"].get<std::uint64_t>(), 0U);
    }
}

TEST(DistributedSurface, CoarseBunnyEqualsTheSerialOctreeAndInstallOn1To4Ranks) {
    test::Scratch s("surface_bunny");
    const SerialMesh ref = serial(surface("gao_bunny_tri.off"), mesher::mesh_preset(mesher::MeshPreset::Coarse), Balance::Weak);
    ASSERT_GT(ref.octree.curvature_splits, 0U);  // every criterion takes part
    ASSERT_EQ(ref.summary.non_cube_vertices, 0U);
    for (int np : {1, 2, 3, 4}) expect_same(ref, dist(np, surface("gao_bunny_tri.off"), {"--preset", "coarse"}, s.dir), np);
}

TEST(DistributedSurface, SizeOptionsAreTheSerialOnesStrongBalance) {
    // --size-rel, --surface-band, --curvature-angle/levels, --thickness-factor as `dualhex mesh` reads them.
    test::Scratch s("surface_fandisk");
    mesher::MeshSizeOptions size;
    size.size_rel = 0.06;
    size.surface_band = 0.5;
    size.curvature_angle = 30;
    size.curvature_levels = 2;
    size.thickness_factor = 1;
    const SerialMesh ref = serial(surface("cgal_fandisk.off"), size, Balance::Strong);
    const std::vector<std::string> options{"--size-rel", "0.06", "--surface-band", "0.5", "--curvature-angle", "30",
                                           "--curvature-levels", "2", "--thickness-factor", "1", "--balance", "strong"};
    const nlohmann::json doc = dist(3, surface("cgal_fandisk.off"), options, s.dir);
    expect_same(ref, doc, 3);
    // The comparison can fail: without the curvature criterion the octree and its mesh differ.
    std::vector<std::string> flat = options;
    flat[5] = "0";
    const nlohmann::json other = dist(2, surface("cgal_fandisk.off"), flat, s.dir);
    EXPECT_LT(other["octree"]["leaves"].get<std::size_t>(), ref.octree.grid.size());
    EXPECT_NE(other["summary"]["hex_hash"], doc["summary"]["hex_hash"]);
}

TEST(DistributedSurface, PiecesAreInModelUnits) {
    test::Scratch s("surface_pvtu");
    const fs::path prefix = s.dir / "bunny";
    const auto r = test::run_dist(2, {"--surface", surface("gao_bunny_tri.off").string(), "--preset", "coarse", "-o",
                                      prefix.string(), "--json"}, s.dir);
    ASSERT_EQ(r.rc, 0) << r.err;
    const nlohmann::json doc = nlohmann::json::parse(r.out);
    const auto& origin = doc["root"]["origin"];
    const double size = doc["root"]["size"].get<double>();
    const std::string text = test::slurp(s.dir / "bunny_1.vtu");
    const auto a = text.find("<Points>"), b = text.find("</DataArray>", a);
    std::istringstream in(text.substr(text.find('>', text.find("<DataArray", a)) + 1, b));
    std::size_t n = 0;
    double x = 0, y = 0, z = 0;
    while (in >> x >> y >> z) {  // inside the root cube around the bunny, not the unit cube
        EXPECT_GE(x, origin[0].get<double>() - 1e-9);
        EXPECT_LE(z, origin[2].get<double>() + size + 1e-9);
        ++n;
    }
    EXPECT_GT(n, 100U);
    EXPECT_LT(origin[0].get<double>(), -0.1) << "the bunny's root cube is not the unit cube";
}

TEST(DistributedSurface, BadSurfaceSizeOrBudgetIsRefusedOnEveryRankCount) {
    test::Scratch s("surface_bad");
    const fs::path bad = s.dir / "bad.off";
    std::ofstream(bad) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
    const auto r = test::run_dist(3, {"--surface", bad.string()}, s.dir);
    EXPECT_EQ(r.rc, 3) << r.err;
    EXPECT_NE(r.err.find("bad.off"), std::string::npos) << r.err;
    const auto missing = test::run_dist(1, {"--surface", (s.dir / "none.off").string()}, s.dir);
    EXPECT_EQ(missing.rc, 3) << missing.err;
    const auto size = test::run_dist(1, {"--surface", surface("gao_bunny_tri.off").string(), "--size", "-1"}, s.dir);
    EXPECT_EQ(size.rc, 2) << size.err;
    EXPECT_NE(size.err.find("--size"), std::string::npos) << size.err;
    // A coarse size (the estimate passes) with thin-part refinement that outgrows the budget:
    // refused by the global count after a level, on every rank.
    const auto budget = test::run_dist(2, {"--surface", surface("gao_bunny_tri.off").string(), "--size-rel", "0.2",
                                           "--thickness-factor", "0.05", "--thickness-levels", "4", "--max-leaves",
                                           "3000"}, s.dir);
    EXPECT_EQ(budget.rc, 2) << budget.err;
    EXPECT_NE(budget.err.find("surface octree: more than 3000 leaves"), std::string::npos) << budget.err;
    const auto both = test::run_dist(1, {(s.dir / "x.leaves").string(), "--surface", bad.string()}, s.dir);
    EXPECT_EQ(both.rc, 2) << both.err;
}

}  // namespace
}  // namespace dualhex

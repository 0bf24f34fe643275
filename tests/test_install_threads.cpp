// Parallel install + clipped dual give bit-identical results for any number of threads:
// the shared grids and random grids installed under task arenas of 1, 2, 3 and 4 threads
// (1 thread: the serial builder; more: the chunked parallel welding with a thread-dependent
// chunk size), compared vertex by vertex, face by face, cell by cell, dual point by dual
// point and hex by hex, and the written VTK files byte for byte. Also the grid checks
// (is_paired / is_balanced, parallel) on grids that pass and fail.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include <unistd.h>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "dualhex/geometry/complex_output.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/grid/refinement.hpp"
#include "dualhex/install.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "test_grid_generators.hpp"
#include "sanitized.hpp"

namespace dualhex {
namespace {

// Under AddressSanitizer (about 10x slower) the grids are smaller: d5 only, random depth 3.
using testing::kSanitized;

const ElementLibrary& library() {
    static const std::shared_ptr<const ElementLibrary> lib = load_default_element_library();
    return *lib;
}

// Everything one run produces: the installation, its clipped dual, the two VTK files.
struct Run {
    InstallResult installed;
    ClippedDual dual;
    std::string poly_vtk, hex_vtk;
};

std::string read_all(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The files as `dualhex install` writes them (same writers, same embedding).
void write_files(Run& r, const std::string& tag) {
    // Unique per process: ctest may run this binary's tests side by side.
    const auto dir = std::filesystem::temp_directory_path();
    const std::string stem = "dualhex_threads_" + std::to_string(::getpid()) + "_" + tag;
    const std::string poly = (dir / (stem + ".poly.vtk")).string(), hex = (dir / (stem + ".hex.vtk")).string();
    const std::int64_t extent = r.installed.unit << r.installed.max_level;
    const double scale = 1.0 / static_cast<double>(extent);
    geometry::write_complex_vtk(poly, r.installed.complex, geometry::LatticeEmbedding{Eigen::Vector3d::Zero(), scale}, true);
    geometry::HexMesh mesh;
    for (const RationalPoint& p : r.dual.points)
        mesh.points.emplace_back(p.coordinate(0, extent), p.coordinate(1, extent), p.coordinate(2, extent));
    for (const auto& h : r.dual.hexes) {
        std::array<int, 8> q{};
        for (std::size_t i = 0; i < 8; ++i) q[i] = static_cast<int>(h[i]);
        mesh.hexes.push_back(q);
    }
    geometry::write_vtk_legacy(hex, mesh, true);
    r.poly_vtk = read_all(poly);
    r.hex_vtk = read_all(hex);
    std::filesystem::remove(poly);
    std::filesystem::remove(hex);
}

Run run(const LeafGrid& grid, const TransitionRule& rule, const InstallOptions& options, int threads, bool files) {
    // Allow more threads than cores (this machine may have fewer than 4), then cap the arena.
    const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
    tbb::task_arena arena(threads);
    Run r;
    arena.execute([&] {
        r.installed = install(grid, rule, library(), options);
        const std::int64_t extent = r.installed.unit << r.installed.max_level;
        const Incidence inc(r.installed.complex);
        r.dual = clipped_dual(r.installed.complex, inc, {0, 0, 0}, {extent, extent, extent});
    });
    if (files) write_files(r, std::to_string(threads));
    return r;
}

// Compares two runs exactly; returns the first difference ("" if none).
std::string difference(const Run& a, const Run& b) {
    const CellComplex &x = a.installed.complex, &y = b.installed.complex;
    if (x.n_vertices() != y.n_vertices() || x.n_faces() != y.n_faces() || x.n_cells() != y.n_cells() || x.n_edges() != y.n_edges())
        return "sizes";
    for (std::size_t v = 0; v < x.n_vertices(); ++v)
        if (x.position(VertexHandle(v)) != y.position(VertexHandle(v))) return "vertex " + std::to_string(v);
    if (x.face_offsets() != y.face_offsets() || x.face_loops() != y.face_loops()) return "faces";
    if (x.cell_offsets() != y.cell_offsets() || x.all_cell_halffaces() != y.all_cell_halffaces()) return "cells";
    for (std::size_t e = 0; e < x.n_edges(); ++e)
        if (x.edge_vertices(EdgeHandle(e)) != y.edge_vertices(EdgeHandle(e))) return "edge " + std::to_string(e);
    if (a.installed.leaf_cells != b.installed.leaf_cells || a.installed.leaf_element != b.installed.leaf_element ||
        a.installed.leaf_symmetry != b.installed.leaf_symmetry || a.installed.element_names != b.installed.element_names)
        return "per-leaf records";
    const ClippedDual &p = a.dual, &q = b.dual;
    if (p.points.size() != q.points.size() || p.hexes != q.hexes || p.primal_vertex != q.primal_vertex || p.kind != q.kind ||
        p.primal != q.primal || p.errors.size() != q.errors.size())
        return "clipped dual";
    for (std::size_t i = 0; i < p.points.size(); ++i)
        if (p.points[i].sum != q.points[i].sum || p.points[i].denominator != q.points[i].denominator)
            return "dual point " + std::to_string(i);
    if (a.poly_vtk != b.poly_vtk) return "poly.vtk bytes";
    if (a.hex_vtk != b.hex_vtk) return "hex.vtk bytes";
    return "";
}

void expect_same_for_all_threads(const LeafGrid& grid, const TransitionRule& rule, const InstallOptions& options) {
    const Run serial = run(grid, rule, options, 1, true);
    ASSERT_GT(serial.dual.hexes.size(), 0U);
    for (int threads : {2, 3, 4}) EXPECT_EQ(difference(serial, run(grid, rule, options, threads, true)), "") << threads << " threads";
}

const std::filesystem::path kGrids = std::filesystem::path(DUALHEX_SHARED_DATA) / "grids";

TEST(InstallThreads, SharedStrongGridsAreBitIdentical) {
    for (const char* name : {"sphere_strong_d5", "sphere_strong_d6"}) {
        if (kSanitized && std::string(name) == "sphere_strong_d6") continue;
        SCOPED_TRACE(name);
        expect_same_for_all_threads(read_leaf_file(kGrids / (std::string(name) + ".leaves")), StrongRule(), {});
    }
}

TEST(InstallThreads, SharedWeakGridIsBitIdenticalBothRootPolicies) {
    const LeafGrid grid = read_leaf_file(kGrids / "sphere_weak_d5.leaves");
    for (OutsideRoot outside : {OutsideRoot::Coarse, OutsideRoot::Mirror})
        expect_same_for_all_threads(grid, WeakRule(), {.outside_root = outside, .balance = Balance::Weak});
}

TEST(InstallThreads, FirstFailingLeafIsTheSerialOne) {
    // The flat-only rule refuses every non-flat pattern: the error must name the first such
    // leaf in leaf order whatever the threads.
    const LeafGrid grid = read_leaf_file(kGrids / "sphere_strong_d5.leaves");
    std::string messages[2];
    const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
    for (int i = 0; i < 2; ++i) {
        tbb::task_arena arena(i == 0 ? 1 : 4);
        arena.execute([&] {
            try {
                (void)install(grid, FlatOnlyRule(), library());
            } catch (const InstallError& e) {
                messages[i] = e.what();
            }
        });
    }
    EXPECT_FALSE(messages[0].empty());
    EXPECT_EQ(messages[0], messages[1]);
}

RC_GTEST_PROP(InstallThreads, RandomGridsAreBitIdentical, ()) {
    const LeafGrid grid = pair(*testing::gen_octree(kSanitized ? 3 : 4), Balance::Strong);
    const Run serial = run(grid, StrongRule(), {}, 1, false);
    for (int threads : {2, 3, 4}) RC_ASSERT(difference(serial, run(grid, StrongRule(), {}, threads, false)) == "");
}

RC_GTEST_PROP(InstallThreads, GridChecksAgreeWithSerial, ()) {
    const LeafGrid grid = *testing::gen_octree(kSanitized ? 3 : 4);
    GridCheck serial[3], parallel[3];
    const auto checks = [&](GridCheck* out) {
        out[0] = is_paired(grid);
        out[1] = is_balanced(grid, Balance::Strong);
        out[2] = is_balanced(grid, Balance::Weak);
    };
    const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
    tbb::task_arena(1).execute([&] { checks(serial); });
    tbb::task_arena(4).execute([&] { checks(parallel); });
    for (int i = 0; i < 3; ++i) {
        RC_ASSERT(serial[i].ok == parallel[i].ok);
        RC_ASSERT(serial[i].message == parallel[i].message);
    }
}

}  // namespace
}  // namespace dualhex

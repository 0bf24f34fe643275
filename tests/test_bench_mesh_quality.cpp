// The independent measurement program bench/mesh_quality: shown hand-made meshes whose
// defects and Euler characteristics are counted by hand, bad VTK files (the error must
// name file and line), and random block selections where its counts must agree with the
// geometry layer's check_hex_topology (two independent implementations).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <sstream>

#include "dualhex/geometry/hex_topology.hpp"
#include "run_process.hpp"
#include "test_geometry_fixture.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex::geometry;
using namespace geometry_test;

namespace {

struct Row {
    std::size_t hexes = 0, inverted = 0, nm_edges = 0, nm_vertices = 0, components = 0;
    std::string boundary_components, chi;
    double max_distance = 0;
};

// Runs mesh_quality on `mesh` (written as VTK) against the unit cube; parses its row.
Row measure(const TempDir& dir, const HexMesh& mesh, const std::string& name) {
    const std::string vtk = dir.file(name + ".vtk");
    write_vtk_legacy(vtk, mesh, true);
    const std::string cube = write_text(dir.file("cube.off"), off_text(unit_cube_surface()));
    const auto r = dualhex::test::run_process(MESH_QUALITY_EXE, {vtk, cube, name}, dir.path);
    EXPECT_EQ(r.rc, 0) << r.err;
    std::istringstream in(r.out);
    std::string label;
    double min_sj, low3, low5, mean, on;
    int max_valence;
    double singular;
    Row row;
    in >> label >> row.hexes >> min_sj >> low3 >> low5 >> row.inverted >> mean >> row.max_distance >> on >>
        row.nm_edges >> row.nm_vertices >> row.components >> row.boundary_components >> row.chi >> max_valence >>
        singular;
    EXPECT_TRUE(in) << "unparsed row: " << r.out;
    EXPECT_EQ(label, name);
    return row;
}

}  // namespace

TEST(BenchMeshQuality, HandCountedTopology) {
    const TempDir dir;
    const Row edge = measure(dir, picked_mesh(hex_block(2, 2, 1), [](int i, int j, int) { return i == j; }), "edge");
    EXPECT_EQ(edge.nm_edges, 1u);
    EXPECT_EQ(edge.nm_vertices, 2u);
    EXPECT_EQ(edge.components, 2u);
    EXPECT_EQ(edge.chi, "3/2");
    const Row vertex =
        measure(dir, picked_mesh(hex_block(2, 2, 2), [](int i, int j, int k) { return i == j && j == k; }), "vertex");
    EXPECT_EQ(vertex.nm_edges, 0u);
    EXPECT_EQ(vertex.nm_vertices, 1u);
    const Row ring =
        measure(dir, picked_mesh(hex_block(3, 3, 2), [](int i, int j, int) { return !(i == 1 && j == 1); }), "ring");
    EXPECT_EQ(ring.nm_edges + ring.nm_vertices, 0u);
    EXPECT_EQ(ring.chi, "0/2");
    const Row hollow = measure(
        dir, picked_mesh(hex_block(3, 3, 3), [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); }), "hollow");
    EXPECT_EQ(hollow.boundary_components, "2/1");
    EXPECT_EQ(hollow.chi, "4/2");
    HexMesh cube = hex_block(2, 2, 2, 0.5).mesh;
    EXPECT_NEAR(measure(dir, cube, "cube").max_distance, 0.0, 1e-3);
    for (auto& p : cube.points) p.x() += 0.1;  // shifted by 0.1: 0.1 / sqrt(3) of the diagonal
    EXPECT_NEAR(measure(dir, cube, "shifted").max_distance, 10.0 / std::sqrt(3.0), 1e-3);
    HexMesh mirrored = hex_block(1, 1, 1).mesh;
    for (int c = 0; c < 4; ++c) std::swap(mirrored.hexes[0][c], mirrored.hexes[0][c + 4]);
    EXPECT_EQ(measure(dir, mirrored, "mirrored").inverted, 1u);
}

TEST(BenchMeshQuality, BadFilesNameFileAndLine) {
    const TempDir dir;
    const std::string cube = write_text(dir.file("cube.off"), off_text(unit_cube_surface()));
    const std::string head =
        "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {head + "CELLS 1 9\n8 0 1 2 3 4 5 6 9\nCELL_TYPES 1\n12\n", ":15: cell 0: point id 9 out of range"},
        {head + "CELLS 1 9\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 1\n10\n", ":17: cell 0 has a cell type other than 12"},
        {head + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n9\n", ":15: cell 0 is not a hexahedron"},
        {head + "CELLS 99999999 9\n", ":14: cell count 99999999 does not fit"},
        {"# vtk DataFile Version 2.0\nt\nBINARY\n", ":3: only ASCII VTK is read"},
        {head.substr(0, head.size() - 8), ":12: unexpected end of file"},
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const std::string vtk = write_text(dir.file("bad" + std::to_string(i) + ".vtk"), cases[i].first);
        const auto r = dualhex::test::run_process(MESH_QUALITY_EXE, {vtk, cube}, dir.path);
        EXPECT_EQ(r.rc, 3) << i;
        EXPECT_NE(r.err.find("bad" + std::to_string(i) + ".vtk" + cases[i].second), std::string::npos)
            << i << ": " << r.err;
    }
}

RC_GTEST_PROP(BenchMeshQuality, AgreesWithTheGeometryChecker, ()) {
    const HexBlock b = hex_block(3, 3, 2);
    auto keep = *rc::gen::container<std::vector<char>>(b.mesh.hexes.size(), rc::gen::element(char{0}, char{1}));
    keep[0] = 1;  // never empty
    const HexMesh m = selected_mesh(b.mesh, keep);
    const TempDir dir;
    const Row row = measure(dir, m, "random");
    const HexTopology t = check_hex_topology(m);
    RC_ASSERT(row.nm_edges == t.non_manifold_edges);
    RC_ASSERT(row.nm_vertices == t.non_manifold_vertices);
    RC_ASSERT(row.components == t.hex_components);
    std::int64_t chi = 0;
    for (const auto& c : t.boundary_components) chi += c.euler();
    RC_ASSERT(row.chi == std::to_string(chi) + "/2");
    RC_ASSERT(row.boundary_components == std::to_string(t.boundary_components.size()) + "/1");
}

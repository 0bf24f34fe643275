// Per-cell data in the hex writers (scaled Jacobian, level: VTK legacy CELL_DATA, VTU
// <CellData>, MEDIT references) and the mesher's per-hex levels (mesher/cell_levels.hpp):
// checked against the leaves around each hex's primal vertex, computed independently.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/geometry/quality.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/mesher/cell_levels.hpp"
#include "dualhex/mesher/install_stage.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "test_geometry_fixture.hpp"

using namespace dualhex;
using namespace dualhex::geometry;
using namespace geometry_test;

namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Two unit hexes side by side along x (12 points).
geometry::HexMesh two_hexes() {
    geometry::HexMesh m;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 3; ++i) m.points.emplace_back(i, j, k);
    auto id = [](int i, int j, int k) { return i + 3 * j + 6 * k; };
    for (int i = 0; i < 2; ++i)
        m.hexes.push_back({id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0), id(i, 0, 1), id(i + 1, 0, 1),
                           id(i + 1, 1, 1), id(i, 1, 1)});
    return m;
}

TEST(CellData, VtkLegacyHasBothScalarsAfterTheCells) {
    TempDir dir;
    const HexCellData data{{0.5, 1.0}, {3, 7}};
    write_vtk_legacy(dir.file("m.vtk"), two_hexes(), false, data);
    const std::string text = slurp(dir.file("m.vtk"));
    const auto cell_data = text.find("CELL_DATA 2\n");
    ASSERT_NE(cell_data, std::string::npos) << text;
    EXPECT_GT(cell_data, text.find("CELL_TYPES 2\n"));
    EXPECT_NE(text.find("SCALARS scaled_jacobian double 1\nLOOKUP_TABLE default\n0.5\n1\n"), std::string::npos) << text;
    EXPECT_NE(text.find("SCALARS level int 1\nLOOKUP_TABLE default\n3\n7\n"), std::string::npos) << text;
}

TEST(CellData, VtuHasACellDataBlockBeforeThePoints) {
    TempDir dir;
    write_vtu(dir.file("m.vtu"), two_hexes(), false, {{0.25, 0.75}, {2, 4}});
    const std::string text = slurp(dir.file("m.vtu"));
    const auto block = text.find("<CellData Scalars=\"scaled_jacobian\">");
    ASSERT_NE(block, std::string::npos) << text;
    EXPECT_LT(block, text.find("<Points>"));
    EXPECT_NE(text.find("<DataArray type=\"Float64\" Name=\"scaled_jacobian\" format=\"ascii\">\n          0.25\n"
                        "          0.75\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("<DataArray type=\"Int32\" Name=\"level\" format=\"ascii\">\n          2\n          4\n"),
              std::string::npos)
        << text;
}

TEST(CellData, MeditTakesTheLevelAsReference) {
    TempDir dir;
    write_medit(dir.file("a.mesh"), two_hexes(), false, {{}, {5, 6}});
    EXPECT_NE(slurp(dir.file("a.mesh")).find("Hexahedra\n2\n1 2 5 4 7 8 11 10 5\n2 3 6 5 8 9 12 11 6\n"),
              std::string::npos)
        << slurp(dir.file("a.mesh"));
    write_medit(dir.file("b.mesh"), two_hexes());
    EXPECT_NE(slurp(dir.file("b.mesh")).find("1 2 5 4 7 8 11 10 0\n"), std::string::npos);
}

TEST(CellData, NoDataNoSectionAndAWrongCountIsRefused) {
    TempDir dir;
    write_vtk_legacy(dir.file("plain.vtk"), two_hexes());
    EXPECT_EQ(slurp(dir.file("plain.vtk")).find("CELL_DATA"), std::string::npos);
    write_vtu(dir.file("plain.vtu"), two_hexes());
    EXPECT_EQ(slurp(dir.file("plain.vtu")).find("CellData"), std::string::npos);
    for (const char* name : {"bad.vtk", "bad.vtu", "bad.mesh"}) {
        EXPECT_THROW(write_hex_mesh(dir.file(name), two_hexes(), false, {{1.0}, {}}), std::runtime_error) << name;
        EXPECT_THROW(write_hex_mesh(dir.file(name), two_hexes(), false, {{}, {1, 2, 3}}), std::runtime_error) << name;
        EXPECT_FALSE(std::filesystem::exists(dir.file(name))) << name;
    }
}

// Uniform level 2, the level-1 octant [0, 1/2]^3 at level 3 (paired: whole sibling groups).
LeafGrid one_octant_refined() {
    std::string text;
    auto add = [&](int level, int i, int j, int k) {
        for (int v : {level, i, j, k}) text += std::to_string(v) + ' ';
        text += '\n';
    };
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) {
                if (i >= 2 || j >= 2 || k >= 2) add(2, i, j, k);
                add(3, i, j, k);
            }
    return parse_leaves(text, "<test>");
}

TEST(CellLevels, HexLevelIsTheFinestLeafAroundItsVertex) {
    const LeafGrid grid = one_octant_refined();
    for (Balance balance : {Balance::Weak, Balance::Strong}) {
        const InstallResult installed = mesher::install_schemes(grid, balance);
        const ClippedDual dual = mesher::root_clipped_dual(installed);
        const std::vector<int> levels = mesher::dual_hex_levels(dual, installed, grid);
        ASSERT_EQ(levels.size(), dual.hexes.size());
        const std::int64_t half = mesher::root_extent(installed) / 2;  // the refined octant is [0, half]^3
        std::size_t fine = 0;
        for (std::size_t h = 0; h < levels.size(); ++h) {
            const LatticePoint& p = installed.complex.position(dual.primal_vertex[h]);
            const bool in_refined_octant = p.x <= half && p.y <= half && p.z <= half;
            EXPECT_EQ(levels[h], in_refined_octant ? 3 : 2) << "hex " << h << " at " << p;
            fine += in_refined_octant ? 1 : 0;
        }
        EXPECT_GE(fine, 125u);  // at least the level-3 corners, 5^3
        EXPECT_LT(fine, levels.size());
    }
}

TEST(CellLevels, PipelineCellDataHasOneValuePerHex) {
    const AabbTree tree(read_surface(shared_surface("cgal_cube.off")));
    mesher::MeshPipelineOptions o;
    o.size = 0.16;  // level 4 at the surface
    o.curvature_angle = 0;
    const mesher::MeshPipelineResult r = mesher::mesh_surface(tree, o);
    const HexCellData& data = r.cell_data;
    ASSERT_EQ(data.level.size(), r.mesh.hexes.size());
    ASSERT_EQ(data.scaled_jacobian.size(), r.mesh.hexes.size());
    EXPECT_EQ(data.scaled_jacobian, scaled_jacobians(r.mesh));  // of the final mesh
    // Boundary hexes sit around vertices of the crossing cells: level 4; the inside is coarser.
    std::vector<char> on_boundary(r.mesh.points.size(), 0);
    for (const auto& q : boundary_quads(r.mesh))
        for (int v : q) on_boundary[v] = 1;
    std::size_t boundary = 0, coarser = 0;
    for (std::size_t h = 0; h < r.mesh.hexes.size(); ++h) {
        EXPECT_LE(data.level[h], 4);
        const bool touches = std::any_of(r.mesh.hexes[h].begin(), r.mesh.hexes[h].end(),
                                         [&](int v) { return on_boundary[v] != 0; });
        if (touches) {
            ++boundary;
            EXPECT_EQ(data.level[h], 4) << "boundary hex " << h;
        }
        coarser += data.level[h] < 4 ? 1 : 0;
    }
    EXPECT_GT(boundary, 0u);
    EXPECT_GT(coarser, 0u);
}

}  // namespace

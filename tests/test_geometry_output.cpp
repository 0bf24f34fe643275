// Hex mesh and polyhedral complex writers: content, overwrite protection, bad input.
// (Reading the files back with meshio is the CTest test geometry_meshio_readback.)
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "dualhex/geometry/complex_output.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/grid/grid_complex.hpp"
#include "test_geometry_fixture.hpp"

using namespace dualhex;
using namespace dualhex::geometry;
using namespace geometry_test;

namespace {

HexMesh unit_cube_hex() {
    HexMesh m;
    for (const auto& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0),
                          Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1),
                          Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(0, 1, 1)})
        m.points.push_back(p);
    m.hexes.push_back({0, 1, 2, 3, 4, 5, 6, 7});
    return m;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(HexOutput, WritesEveryFormat) {
    TempDir dir;
    const HexMesh m = unit_cube_hex();
    write_hex_mesh(dir.file("c.vtk"), m);
    write_hex_mesh(dir.file("c.vtu"), m);
    write_hex_mesh(dir.file("c.mesh"), m);
    const auto vtk = slurp(dir.file("c.vtk"));
    EXPECT_NE(vtk.find("POINTS 8 double"), std::string::npos);
    EXPECT_NE(vtk.find("CELLS 1 9\n8 0 1 2 3 4 5 6 7\n"), std::string::npos);
    EXPECT_NE(vtk.find("CELL_TYPES 1\n12\n"), std::string::npos);
    const auto vtu = slurp(dir.file("c.vtu"));
    EXPECT_NE(vtu.find("NumberOfPoints=\"8\" NumberOfCells=\"1\""), std::string::npos);
    const auto medit = slurp(dir.file("c.mesh"));
    EXPECT_NE(medit.find("Hexahedra\n1\n1 2 3 4 5 6 7 8 0\n"), std::string::npos);
    EXPECT_NE(medit.find("Vertices\n8\n"), std::string::npos);
}

TEST(HexOutput, NeverOverwritesUnlessAsked) {
    TempDir dir;
    const auto path = write_text(dir.file("keep.vtk"), "precious\n");
    HexMesh m = unit_cube_hex();
    for (const char* name : {"keep.vtk"}) {
        try {
            write_vtk_legacy(dir.file(name), m);
            ADD_FAILURE() << "overwrote " << name;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(slurp(path), "precious\n");
    const auto vtu = write_text(dir.file("keep.vtu"), "x");
    const auto mesh = write_text(dir.file("keep.mesh"), "x");
    EXPECT_THROW(write_vtu(vtu, m), std::runtime_error);
    EXPECT_THROW(write_medit(mesh, m), std::runtime_error);
    EXPECT_EQ(slurp(vtu), "x");
    EXPECT_EQ(slurp(mesh), "x");
    write_vtk_legacy(path, m, /*overwrite=*/true);
    EXPECT_NE(slurp(path).find("CELL_TYPES 1"), std::string::npos);
}

TEST(HexOutput, BadInputIsRefusedBeforeWriting) {
    TempDir dir;
    HexMesh m = unit_cube_hex();
    m.hexes[0][3] = 8;
    EXPECT_THROW(write_vtk_legacy(dir.file("bad.vtk"), m), std::runtime_error);
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.vtk")));
    EXPECT_THROW(write_hex_mesh(dir.file("c.obj"), unit_cube_hex()), std::invalid_argument);
    EXPECT_THROW(write_vtk_legacy((dir.path / "no_such_dir" / "c.vtk").string(), unit_cube_hex()),
                 std::runtime_error);
}

TEST(ComplexOutput, WritesPolyhedraWithOutwardFaces) {
    TempDir dir;
    const CellComplex c = leaves_to_complex(leaf_box(1, {0, 0, 0}, {2, 2, 2}));
    ASSERT_EQ(c.n_cells(), 8u);
    ASSERT_EQ(c.n_vertices(), 27u);
    LatticeEmbedding embed;
    embed.scale = 0.5;
    embed.origin = Eigen::Vector3d(1, 2, 3);
    const auto path = dir.file("box.vtk");
    write_complex_vtk(path, c, embed);
    std::istringstream in(slurp(path));
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(in, line)) lines.push_back(line);
    ASSERT_GT(lines.size(), 40u);
    EXPECT_EQ(lines[4], "POINTS 27 double");
    EXPECT_EQ(lines[5], "1 2 3");  // lattice (0,0,0)
    // Each cell: 1 size + 1 face count + 6 * (1 + 4) = 32 numbers; the list = 8 * 32.
    EXPECT_EQ(lines[5 + 27], "CELLS 8 256");
    EXPECT_EQ(lines[5 + 27 + 1].substr(0, 5), "31 6 ");
    EXPECT_EQ(lines[5 + 27 + 9], "CELL_TYPES 8");
    EXPECT_EQ(lines[5 + 27 + 10], "42");
    EXPECT_THROW(write_complex_vtk(path, c, embed), std::runtime_error);
    write_complex_vtk(path, c, embed, true);
}

}  // namespace

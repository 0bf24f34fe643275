// The audit's readers: they read exactly what dualhex's writers write (hex meshes in all
// three formats, polyhedral complexes), VTU inline base64 binary equals its ASCII twin,
// and malformed files are refused with an InputError naming the file and line.
#include <sys/stat.h>

#include <cstring>

#include <gtest/gtest.h>

#include "dualhex/audit/read_mesh.hpp"
#include "dualhex/geometry/complex_output.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/grid/input_error.hpp"
#include "test_audit_fixture.hpp"
#include "test_geometry_hex_block.hpp"

namespace {

using namespace dualhex::audit;
using audit_test::TempDir;

class AuditReaders : public TempDir {};

// Irrational-looking coordinates: the round trip must be exact (17 significant digits).
dualhex::geometry::HexMesh skewed_block() {
    auto m = geometry_test::hex_block(2, 2, 1, 0.1, Eigen::Vector3d(1.0 / 3.0, -2.0 / 7.0, 1e-9)).mesh;
    m.points[4].x() += 0.0123456789;
    return m;
}

void expect_same_hexes(const MeshFile& f, const dualhex::geometry::HexMesh& m) {
    ASSERT_EQ(f.points.size(), m.points.size());
    for (std::size_t i = 0; i < m.points.size(); ++i)
        for (int a = 0; a < 3; ++a) EXPECT_EQ(f.points[i][static_cast<std::size_t>(a)], m.points[i][a]) << i;
    ASSERT_EQ(f.cells.size(), m.hexes.size());
    for (std::size_t h = 0; h < m.hexes.size(); ++h) {
        EXPECT_EQ(f.cells[h].type, kVtkHexahedron);
        EXPECT_EQ(f.cells[h].index, h);
        EXPECT_GT(f.cells[h].line, 0);
        EXPECT_EQ(f.cells[h].points, std::vector<std::int64_t>(m.hexes[h].begin(), m.hexes[h].end()));
    }
}

TEST_F(AuditReaders, ReadsWhatTheHexWritersWrite) {
    const auto m = skewed_block();
    for (const std::string ext : {".vtk", ".vtu", ".mesh"}) {
        const std::string p = path("block" + ext);
        dualhex::geometry::write_hex_mesh(p, m);
        SCOPED_TRACE(p);
        expect_same_hexes(read_mesh(p), m);
    }
}

TEST_F(AuditReaders, ReadsWhatTheComplexWriterWrites) {
    auto groups = audit_test::unit_cubes(2);
    audit_test::merge(groups, {{{0, 0, 1}}, {{1, 0, 1}}});  // one 10-face cell
    const auto k = audit_test::complex_of_cube_groups(groups);
    const std::string p = path("poly.vtk");
    dualhex::geometry::write_complex_vtk(p, k, {Eigen::Vector3d(0.5, 0, 0), 0.25});
    const MeshFile f = read_mesh(p);
    ASSERT_EQ(f.points.size(), k.n_vertices());
    EXPECT_EQ(f.points[3][0], 0.5 + 0.25 * double(k.position(dualhex::VertexHandle(std::size_t{3})).x));
    ASSERT_EQ(f.cells.size(), k.n_cells());
    for (std::size_t c = 0; c < k.n_cells(); ++c) {
        EXPECT_EQ(f.cells[c].type, kVtkPolyhedron);
        const auto hfs = k.cell_halffaces(dualhex::CellHandle(c));
        ASSERT_EQ(f.cells[c].faces.size(), hfs.size());
        for (std::size_t i = 0; i < hfs.size(); ++i) {
            std::vector<std::int64_t> loop;
            for (auto v : k.halfface_vertices(hfs[i])) loop.push_back(v.index());
            EXPECT_EQ(f.cells[c].faces[i], loop);
        }
    }
    EXPECT_EQ(f.cells.back().faces.size(), 10U);
}

// The 2x1x1 block as VTU with every array inline base64 or appended (UInt64 header, header and data
// encoded separately as VTK does) and as ASCII: the same mesh.
TEST_F(AuditReaders, VtuBinaryEqualsAscii) {
    const auto m = geometry_test::hex_block(2, 1, 1, 0.5).mesh;
    dualhex::geometry::write_vtu(path("a.vtu"), m);
    std::vector<double> coords;
    for (const auto& p : m.points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
    std::string coord_bytes;
    for (double x : coords) coord_bytes.append(reinterpret_cast<const char*>(&x), 8);
    std::vector<long> conn, offsets, types;
    for (const auto& h : m.hexes) {
        conn.insert(conn.end(), h.begin(), h.end());
        offsets.push_back(static_cast<long>(conn.size()));
        types.push_back(12);
    }
    auto array = [](const std::string& type, const std::string& name, const std::string& data, int components = 0) {
        const std::string header = audit_test::le_bytes<std::uint64_t>(std::vector<std::uint64_t>{data.size()});
        return "<DataArray type=\"" + type + "\"" + (name.empty() ? "" : " Name=\"" + name + "\"") +
               (components ? " NumberOfComponents=\"3\"" : "") + " format=\"binary\">\n" + audit_test::base64(header) +
               audit_test::base64(data) + "\n</DataArray>\n";
    };
    const std::string text =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(m.points.size()) +
        "\" NumberOfCells=\"2\">\n<Points>\n" + array("Float64", "", coord_bytes, 3) + "</Points>\n<Cells>\n" +
        array("Int64", "connectivity", audit_test::le_bytes<std::int64_t>(conn)) +
        array("Int32", "offsets", audit_test::le_bytes<std::int32_t>(offsets)) +
        array("UInt8", "types", audit_test::le_bytes<std::uint8_t>(types)) +
        "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    // The same arrays appended (raw bytes, and base64 with header and data encoded apart).
    const std::vector<std::pair<std::string, std::string>> blocks{
        {"<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\"", coord_bytes},
        {"<DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"", audit_test::le_bytes<std::int64_t>(conn)},
        {"<DataArray type=\"Int32\" Name=\"offsets\" format=\"appended\" offset=\"", audit_test::le_bytes<std::int32_t>(offsets)},
        {"<DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"", audit_test::le_bytes<std::uint8_t>(types)}};
    for (const bool raw : {true, false}) {
        std::string arrays[4], data;
        for (std::size_t i = 0; i < blocks.size(); ++i) {
            arrays[i] = blocks[i].first + std::to_string(data.size()) + "\"/>\n";
            const std::string header = audit_test::le_bytes<std::uint64_t>(std::vector<std::uint64_t>{blocks[i].second.size()});
            data += raw ? header + blocks[i].second : audit_test::base64(header) + audit_test::base64(blocks[i].second);
        }
        const std::string appended =
            "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
            "<UnstructuredGrid>\n<Piece NumberOfPoints=\"12\" NumberOfCells=\"2\">\n<Points>\n" + arrays[0] +
            "</Points>\n<Cells>\n" + arrays[1] + arrays[2] + arrays[3] + "</Cells>\n</Piece>\n</UnstructuredGrid>\n"
            "<AppendedData encoding=\"" + (raw ? "raw" : "base64") + "\">\n  _" + data + "\n</AppendedData>\n</VTKFile>\n";
        SCOPED_TRACE(raw ? "raw" : "base64");
        expect_same_hexes(read_mesh(write("app.vtu", appended)), m);
        // cut inside the appended data: refused
        EXPECT_THROW((void)read_mesh(write("app_cut.vtu", appended.substr(0, appended.size() - 40))), dualhex::InputError);
    }
    const MeshFile bin = read_mesh(write("b.vtu", text));
    expect_same_hexes(bin, m);
    expect_same_hexes(read_mesh(path("a.vtu")), m);
    // A corrupted base64 character is refused, naming the array's line.
    std::string bad = text;
    bad[bad.find("format=\"binary\">\n") + 18] = '*';
    try {
        (void)read_mesh(write("bad.vtu", bad));
        FAIL() << "bad base64 accepted";
    } catch (const dualhex::InputError& e) {
        EXPECT_EQ(e.line(), 6) << e.what();
        EXPECT_NE(std::string(e.what()).find("base64"), std::string::npos) << e.what();
    }
}

// Big-endian bytes of `values` as `Int` (or double).
template <class T, class Range>
std::string be_bytes(const Range& values) {
    std::string s;
    for (auto v : values) {
        const T t = static_cast<T>(v);
        std::uint64_t u = 0;
        std::memcpy(&u, &t, sizeof(T));
        for (int b = static_cast<int>(sizeof(T)) - 1; b >= 0; --b) s += static_cast<char>((u >> (8 * b)) & 0xff);
    }
    return s;
}

// The 2x1x1 block as BINARY legacy files, classic (CELLS rows, int32) and version 5.1
// (OFFSETS / CONNECTIVITY vtktypeint64, as meshio writes): the same mesh as the ASCII writer's.
TEST_F(AuditReaders, VtkLegacyBinaryEqualsAscii) {
    const auto m = geometry_test::hex_block(2, 1, 1, 0.25).mesh;
    std::vector<double> coords;
    for (const auto& p : m.points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
    std::vector<long> rows, conn, offsets{0}, types(m.hexes.size(), 12);
    for (const auto& h : m.hexes) {
        rows.push_back(8);
        rows.insert(rows.end(), h.begin(), h.end());
        conn.insert(conn.end(), h.begin(), h.end());
        offsets.push_back(static_cast<long>(conn.size()));
    }
    const std::string head = "# vtk DataFile Version 3.0\nbinary\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 12 double\n" +
                             be_bytes<double>(coords) + "\n";
    const std::string classic = head + "CELLS 2 18\n" + be_bytes<std::int32_t>(rows) + "\nCELL_TYPES 2\n" +
                                be_bytes<std::int32_t>(types) + "\n";
    expect_same_hexes(read_mesh(write("classic.vtk", classic)), m);
    const std::string v51 = head + "CELLS 3 16\nOFFSETS vtktypeint64\n" + be_bytes<std::int64_t>(offsets) +
                            "\nCONNECTIVITY vtktypeint64\n" + be_bytes<std::int64_t>(conn) + "\nCELL_TYPES 2\n" +
                            be_bytes<std::int32_t>(types) + "\n";
    expect_same_hexes(read_mesh(write("v51.vtk", v51)), m);
    // Cut inside the binary cell types: refused as truncated.
    try {
        (void)read_mesh(write("cut.vtk", classic.substr(0, classic.size() - 3)));
        FAIL() << "truncated binary file accepted";
    } catch (const dualhex::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("truncated binary CELL_TYPES"), std::string::npos) << e.what();
    }
}

// A polyhedral VTU (faces / faceoffsets, ASCII) mixing a polyhedron and a hexahedron.
TEST_F(AuditReaders, VtuPolyhedraThroughFacesArrays) {
    const auto m = geometry_test::hex_block(2, 1, 1).mesh;
    std::string faces = "6", conn, offsets = "8 16", types = "42 12";
    const int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    for (const auto& f : kFaces) {
        faces += " 4";
        for (int c : f) faces += ' ' + std::to_string(m.hexes[0][static_cast<std::size_t>(c)]);
    }
    for (const auto& h : m.hexes)
        for (int v : h) conn += ' ' + std::to_string(v);
    std::string pts;
    for (const auto& p : m.points) pts += std::to_string(p.x()) + ' ' + std::to_string(p.y()) + ' ' + std::to_string(p.z()) + '\n';
    auto array = [](const std::string& type, const std::string& name, const std::string& data) {
        return "<DataArray type=\"" + type + "\" Name=\"" + name + "\" format=\"ascii\">" + data + "</DataArray>\n";
    };
    const std::string text = "<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"12\" "
                             "NumberOfCells=\"2\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" "
                             "format=\"ascii\">\n" + pts + "</DataArray>\n</Points>\n<Cells>\n" +
                             array("Int64", "connectivity", conn) + array("Int64", "offsets", offsets) +
                             array("UInt8", "types", types) + array("Int64", "faces", faces) +
                             array("Int64", "faceoffsets", "31 -1") + "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    const MeshFile f = read_mesh(write("poly.vtu", text));
    ASSERT_EQ(f.cells.size(), 2U);
    EXPECT_EQ(f.cells[0].type, kVtkPolyhedron);
    ASSERT_EQ(f.cells[0].faces.size(), 6U);
    const auto& h = m.hexes[0];
    EXPECT_EQ(f.cells[0].faces[1], (std::vector<std::int64_t>{h[4], h[5], h[6], h[7]}));  // the top
    EXPECT_EQ(f.cells[1].type, kVtkHexahedron);
}

// Each malformed file: an InputError whose what() is "file:line: ..." naming the value.
struct Malformed {
    std::string name, text;
    int line;
    std::string mentions;
};

class AuditMalformed : public TempDir {};

TEST_F(AuditMalformed, RefusedWithFileLineAndValue) {
    const std::string head = "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    const std::string pts = "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
    const std::string cells = "CELLS 1 5\n4 0 1 2 3\n";
    const std::vector<Malformed> cases{
        {"truncated.vtk", head + "POINTS 2 double\n0.000000 0.000000 0.000000\n1.000000", 7, "end of file"},
        {"short.vtk", head + "POINTS 4 double\n0 0 0\n1 0 0\n0 1", 5, "exceeds what the rest of the file"},
        {"huge_count.vtk", head + "POINTS 1000000000 double\n0 0 0\n", 5, "1000000000"},
        {"bad_number.vtk", head + "POINTS 4 double\n0 0 0\n1 0 0\n0 1 zero\n0 0 1\n", 8, "'zero'"},
        {"bad_type.vtk", head + pts + cells + "CELL_TYPES 1\n99\n", 13, "99"},
        {"wrong_arity.vtk", head + pts + cells + "CELL_TYPES 1\n12\n", 13, "hexahedron with 4 points"},
        {"id_range.vtk", head + pts + "CELLS 1 5\n4 0 1 2 7\n" + "CELL_TYPES 1\n10\n", 11, "point id 7"},
        {"cells_size.vtk", head + pts + "CELLS 1 6\n4 0 1 2 3\n" + "CELL_TYPES 1\n10\n", 10, "CELLS size 6"},
        {"types_count.vtk", head + pts + cells + "CELL_TYPES 2\n10\n10\n", 12, "CELL_TYPES count 2"},
        {"bad_stream.vtk", head + pts + "CELLS 1 6\n5 1 4 0 1 2\n" + "CELL_TYPES 1\n42\n", 11, "face 0"},
        {"not_vtk.vtk", "hello\n\n\n", 1, "not a VTK legacy file"},
        {"truncated.vtu", "<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"4\" "
                          "NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                          "format=\"ascii\">\n0 0 0\n",
         5, "never closed"},
        {"bad_id.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 0 0\nHexahedra\n1\n1 1 1 1 1 1 1 9 0\nEnd\n",
         8, "vertex id 9"},
        {"keyword.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 0 0\nBogus\n1\nEnd\n", 6, "'Bogus'"},
        {"no_end.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 0 0\n", 5, "expected End"},
        {"bad.stl", "solid\n", 0, "unknown mesh format"},
    };
    for (const Malformed& m : cases) {
        const std::string p = write(m.name, m.text);
        try {
            (void)read_mesh(p);
            ADD_FAILURE() << m.name << " accepted";
        } catch (const dualhex::InputError& e) {
            EXPECT_EQ(e.file(), p);
            EXPECT_EQ(e.line(), m.line) << e.what();
            EXPECT_NE(std::string(e.what()).find(m.mentions), std::string::npos) << e.what();
            if (m.line > 0) {
                EXPECT_EQ(std::string(e.what()).rfind(p + ":" + std::to_string(m.line) + ": ", 0), 0U) << e.what();
            }
        }
    }
}

TEST_F(AuditMalformed, NonRegularAndMissingFilesRefusedWithoutHanging) {
    const std::string fifo = path("pipe.vtk");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_THROW((void)read_mesh(fifo), dualhex::InputError);  // would block if opened
    EXPECT_THROW((void)read_mesh(dir_.string() + "/sub.vtk/"), dualhex::InputError);
    std::filesystem::create_directory(path("dir.vtk"));
    try {
        (void)read_mesh(path("dir.vtk"));
        FAIL();
    } catch (const dualhex::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)read_mesh(path("missing.mesh")), dualhex::InputError);
}

}  // namespace

// The .element format: round trip and precise parser errors (file:line: entity).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "dualhex/schemes/element.hpp"
#include "dualhex/schemes/element_library.hpp"

using namespace dualhex;
namespace fs = std::filesystem;

namespace {

fs::path elements_dir() { return fs::path(DUALHEX_SOURCE_DIR) / "schemes" / "elements"; }

fs::path temp_dir(const std::string& name) {
    auto d = fs::temp_directory_path() / ("dualhex_schemes_format_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

const char* kHeader =
    "dualhex-element 1\n"  // line 1
    "name T\n"             // line 2
    "leaf 2\n";            // line 3
// a valid tetrahedron-free 'cube' (one hex cell) of leaf 2, lines 4..18
const char* kCube =
    "vertex 0 0 0 0\nvertex 1 2 0 0\nvertex 2 2 2 0\nvertex 3 0 2 0\n"
    "vertex 4 0 0 2\nvertex 5 2 0 2\nvertex 6 2 2 2\nvertex 7 0 2 2\n"
    "cell hex\n"
    "face 0 3 2 1\nface 4 5 6 7\nface 0 1 5 4\nface 2 3 7 6\nface 1 2 6 5\nface 0 4 7 3\n"
    "end\n";

}  // namespace

TEST(SchemesFormat, CubeParsesAndIsValid) {
    const auto d = parse_element_string(std::string(kHeader) + kCube, "cube");
    EXPECT_EQ(d.name, "T");
    EXPECT_EQ(d.leaf, 2);
    ASSERT_EQ(d.vertices.size(), 8u);
    ASSERT_EQ(d.cells.size(), 1u);
    EXPECT_EQ(d.cells[0].label, "hex");
    EXPECT_EQ(d.cells[0].faces.size(), 6u);
    const auto r = check_element(d);
    EXPECT_TRUE(r.ok()) << [&] { std::ostringstream os; r.print(os); return os.str(); }();
}

TEST(SchemesFormat, CommentsBlankLinesAndArbitraryIds) {
    const std::string text =
        "# leading comment\n\n  dualhex-element 1   # version\nname X\nleaf 2\n"
        "vertex 10 0 0 0\nvertex 7 2 0 0\nvertex 3 0 2 0\nvertex 99 0 0 2\n"
        "cell t # a tetrahedron\nface 10 3 7\nface 10 7 99\nface 10 99 3\nface 7 3 99\nend\n";
    const auto d = parse_element_string(text);
    EXPECT_EQ(d.vertices[0].id, 10);
    EXPECT_EQ(d.vertices[3].position, (LatticePoint{0, 0, 2}));
    EXPECT_EQ(d.cells[0].faces[3], (std::vector<std::int64_t>{7, 3, 99}));
    EXPECT_EQ(parse_element_string(element_to_string(d)), d);
}

TEST(SchemesFormat, SeedFilesRoundTrip) {
    for (const char* name : {"F", "C1"}) {
        const auto d = read_element_file(elements_dir() / (std::string(name) + ".element"));
        EXPECT_EQ(d.name, name);
        EXPECT_EQ(d.leaf, 12);
        const std::string text = element_to_string(d);
        const auto again = parse_element_string(text);
        EXPECT_EQ(again, d) << name;
        EXPECT_EQ(element_to_string(again), text) << name;  // the writer is canonical

        // through a file on disk, with extra comments
        const auto dir = temp_dir(std::string("rt_") + name);
        {
            std::ofstream out(dir / "x.element");
            write_element(out, d, {"round trip", "second comment"});
        }
        EXPECT_EQ(read_element_file(dir / "x.element"), d);
        fs::remove_all(dir);
    }
}

TEST(SchemesFormat, ComplexRoundTrip) {
    const auto d = read_element_file(elements_dir() / "F.element");
    const auto cx = to_complex(d);
    EXPECT_EQ(cx.n_cells(), d.cells.size());
    EXPECT_EQ(cx.n_vertices(), d.vertices.size());
    const auto back = element_from_complex("F", 12, cx, {"p1", "p2", "q", "lid"});
    EXPECT_EQ(parse_element_string(element_to_string(back)), back);
    const auto cx2 = to_complex(back);
    EXPECT_EQ(cx2.n_faces(), cx.n_faces());
    EXPECT_EQ(cx2.n_edges(), cx.n_edges());
    EXPECT_EQ(cx2.positions(), cx.positions());
    EXPECT_EQ(cx2.all_cell_halffaces(), cx.all_cell_halffaces());
    EXPECT_TRUE(check_element(back).ok());
}

struct BadCase {
    const char* name;
    std::string text;
    int line;
    const char* needle;
};

TEST(SchemesFormat, ParserErrorsNameFileAndLine) {
    const std::string h = kHeader;
    const std::string v = "vertex 0 0 0 0\nvertex 1 2 0 0\nvertex 2 0 2 0\n";  // lines 4-6
    const std::vector<BadCase> cases = {
        {"bad_version", "dualhex-element 2\nname T\nleaf 2\n", 1, "unsupported format version 2"},
        {"no_version", "# x\nname T\n", 2, "expected 'dualhex-element"},
        {"empty", "# nothing\n\n", 2, "empty file"},
        {"unknown_directive", h + "vortex 0 0 0 0\n", 4, "unknown directive 'vortex'"},
        {"out_of_range", h + "vertex 0 0 3 0\n", 4, "coordinate 3 outside [0, 2]"},
        {"negative_coord", h + "vertex 0 0 -1 0\n", 4, "coordinate -1 outside"},
        {"duplicate_id", h + "vertex 0 0 0 0\nvertex 0 1 0 0\n", 5, "duplicate vertex id 0 (first declared on line 4)"},
        {"duplicate_position", h + "vertex 0 0 0 0\nvertex 1 0 0 0\n", 5, "same position as vertex 0"},
        {"unknown_vertex", h + v + "cell a\nface 0 1 5\n", 8, "unknown vertex id 5"},
        {"short_face", h + v + "cell a\nface 0 1\n", 8, "face with 2 vertices"},
        {"cell_without_faces", h + v + "cell a\nend\n", 8, "cell 'a' has no faces"},
        {"missing_end_eof", h + v + "cell a\nface 0 1 2\n", 8, "cell 'a' (line 7) not closed by 'end' at end of file"},
        {"missing_end_next", h + v + "cell a\nface 0 1 2\ncell b\n", 9, "cell 'a' (line 7) not closed"},
        {"non_integer_coord", h + "vertex 0 0 1.5 0\n", 4, "expected an integer vertex coordinate, got '1.5'"},
        {"non_integer_id", h + v + "cell a\nface 0 1 two\n", 8, "got 'two'"},
        {"non_integer_leaf", "dualhex-element 1\nname T\nleaf 12x\n", 3, "got '12x'"},
        {"wrong_arity", h + "vertex 0 0 0\n", 4, "'vertex' takes 4 arguments, got 3"},
        {"duplicate_label", h + v + "cell a\nface 0 1 2\nend\ncell a\n", 10, "duplicate cell label 'a'"},
        {"face_outside_cell", h + v + "face 0 1 2\n", 7, "'face' outside a cell"},
        {"end_without_cell", h + "end\n", 4, "'end' without an open cell"},
        {"vertex_before_leaf", "dualhex-element 1\nname T\nvertex 0 0 0 0\n", 3, "'vertex' before 'name' and 'leaf'"},
        {"missing_leaf", "dualhex-element 1\nname T\n", 2, "missing 'leaf'"},
        {"no_cells", h + v, 6, "element without cells"},
        {"bad_name", "dualhex-element 1\nname F/C\n", 2, "bad element name 'F/C'"},
        {"zero_leaf", "dualhex-element 1\nname T\nleaf 0\n", 3, "leaf resolution must be positive"},
    };
    const auto dir = temp_dir("errors");
    for (const auto& c : cases) {
        const auto path = dir / (std::string(c.name) + ".element");
        {
            std::ofstream out(path);
            out << c.text;
        }
        try {
            (void)read_element_file(path);
            ADD_FAILURE() << c.name << ": accepted";
        } catch (const SchemeFormatError& e) {
            EXPECT_EQ(e.file(), path.string()) << c.name;
            EXPECT_EQ(e.line(), c.line) << c.name << ": " << e.what();
            EXPECT_NE(e.message().find(c.needle), std::string::npos) << c.name << ": " << e.what();
            const std::string prefix = path.string() + ":" + std::to_string(c.line) + ": ";
            EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << c.name << ": " << e.what();
        }
    }
    fs::remove_all(dir);
}

TEST(SchemesFormat, MissingFileIsAnError) {
    try {
        (void)read_element_file("/nonexistent/dir/x.element");
        ADD_FAILURE() << "accepted";
    } catch (const SchemeFormatError& e) {
        EXPECT_EQ(e.line(), 0);
        EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
    }
}

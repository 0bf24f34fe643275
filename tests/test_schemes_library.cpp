// The element library (loading, strictness, placement) and the paper's table.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/paper_table.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/validation.hpp"

using namespace dualhex;
namespace fs = std::filesystem;

namespace {

fs::path elements_dir() { return fs::path(DUALHEX_SOURCE_DIR) / "schemes" / "elements"; }

fs::path temp_dir(const std::string& name) {
    auto d = fs::temp_directory_path() / ("dualhex_schemes_lib_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string report(const ElementCheckReport& r) {
    std::ostringstream os;
    r.print(os);
    return os.str();
}

}  // namespace

TEST(SchemesPaperTable, ThirteenRowsAsCited) {
    const auto t = paper_table();
    ASSERT_EQ(t.size(), 13u);
    EXPECT_EQ(t[0].name, "F");
    EXPECT_EQ(t[12].name, "VS-MR");
    const auto f = paper_row("F");
    ASSERT_TRUE(f);
    EXPECT_EQ(f->count(3), 5u);
    EXPECT_EQ(f->count(4), 10u);
    EXPECT_EQ(f->count(5), 5u);
    EXPECT_EQ(f->count(6), 0u);
    EXPECT_EQ(f->count(8), 0u);
    const auto vc3 = paper_row("VC3-MR");
    ASSERT_TRUE(vc3);
    EXPECT_EQ(vc3->counts, (std::array<std::size_t, 5>{30, 12, 6, 6, 3}));
    EXPECT_EQ(paper_row("VC")->counts, (std::array<std::size_t, 5>{9, 21, 0, 6, 0}));
    EXPECT_FALSE(paper_row("nope"));
}

TEST(SchemesPaperTable, ComparisonIsPerColumn) {
    const auto row = *paper_row("C1");
    EXPECT_TRUE(compare_with_paper({{3, 4}, {4, 3}, {5, 3}}, row).matches());
    const auto diff = compare_with_paper({{3, 4}, {4, 2}, {5, 3}, {6, 1}}, row);
    EXPECT_FALSE(diff.matches());
    EXPECT_TRUE(diff.columns[0].equal());
    EXPECT_FALSE(diff.columns[1].equal());
    EXPECT_EQ(diff.columns[1].computed, 2u);
    EXPECT_EQ(diff.columns[1].paper, 3u);
    EXPECT_TRUE(diff.columns[2].equal());
    EXPECT_FALSE(diff.columns[3].equal());
    EXPECT_EQ(diff.summary(), "F3 4=4, F4 2!=3, F5 3=3, F6 1!=0, F7 0=0");
    const auto big = compare_with_paper({{3, 4}, {4, 3}, {5, 3}, {8, 1}}, row);
    EXPECT_FALSE(big.matches());
    EXPECT_EQ(big.outside_table.at(8), 1u);
}

TEST(SchemesLibrary, LoadsSeedElementsValidAndAsInThePaper) {
    const auto lib = ElementLibrary::load(elements_dir());
    EXPECT_EQ(lib.names(), (std::vector<std::string>{"C1", "C2", "C3", "E", "E-MR", "F", "F+C", "VC", "VC1-MR",
                                                    "VC2-MR", "VC3-MR", "VS", "VS-MR"}));
    const std::map<std::string, std::pair<std::size_t, std::map<int, std::size_t>>> expected = {
        // cell counts and face-size histograms of the derived elements (the histograms are
        // also the paper's Table "topology" rows, compared separately below)
        {"F", {4, {{3, 5}, {4, 10}, {5, 5}}}},
        {"F+C", {5, {{3, 9}, {4, 9}, {5, 4}, {6, 2}}}},
        {"C1", {2, {{3, 4}, {4, 3}, {5, 3}}}},
        {"C2", {3, {{3, 8}, {4, 1}, {5, 4}, {6, 1}}}},
        {"C3", {4, {{3, 12}, {5, 3}, {6, 3}}}},
        {"E", {6, {{3, 8}, {4, 14}, {5, 7}, {6, 1}}}},
        {"VC", {7, {{3, 9}, {4, 21}, {6, 6}}}},
        {"VS", {6, {{3, 8}, {4, 16}, {5, 3}, {6, 3}}}},
        {"VS-MR", {8, {{3, 15}, {4, 12}, {5, 7}, {6, 2}, {7, 1}}}},
        {"VC1-MR", {9, {{3, 16}, {4, 17}, {5, 4}, {6, 5}, {7, 1}}}},
        {"VC2-MR", {11, {{3, 23}, {4, 14}, {5, 6}, {6, 5}, {7, 2}}}},
        {"VC3-MR", {13, {{3, 30}, {4, 12}, {5, 6}, {6, 6}, {7, 3}}}},
    };
    for (const auto& [name, exp] : expected) {
        const auto& e = lib.at(name);
        EXPECT_TRUE(e.valid()) << name << "\n" << report(e.check);
        EXPECT_EQ(e.complex.n_cells(), exp.first) << name;
        const auto hist = face_size_histogram(e.complex);
        EXPECT_EQ(hist, exp.second) << name;
        const auto cmp = compare_with_paper(hist, *paper_row(name));
        EXPECT_TRUE(cmp.matches()) << name << ": " << cmp.summary();
        EXPECT_EQ(euler_characteristic(e.complex), 1) << name;
    }
    // E-MR: the derived element has 15 triangles where the paper's row says 14 (the other
    // columns agree); docs/scheme-derivation.md explains why 15 is forced in the construction.
    const auto& emr = lib.at("E-MR");
    EXPECT_TRUE(emr.valid());
    EXPECT_EQ(emr.complex.n_cells(), 8u);
    const auto emr_hist = face_size_histogram(emr.complex);
    EXPECT_EQ(emr_hist, (std::map<int, std::size_t>{{3, 15}, {4, 10}, {5, 10}, {6, 2}}));
    const auto emr_cmp = compare_with_paper(emr_hist, *paper_row("E-MR"));
    EXPECT_FALSE(emr_cmp.matches());
    EXPECT_EQ(emr_cmp.summary().find("F3 15!=14") != std::string::npos, true) << emr_cmp.summary();
    EXPECT_EQ(lib.find("no-such-element"), nullptr);
    EXPECT_THROW((void)lib.at("no-such-element"), std::out_of_range);
}

TEST(SchemesLibrary, SymmetryPlacedInstancesStayValid) {
    const auto lib = ElementLibrary::load(elements_dir());
    for (const char* name : {"F", "F+C", "C1", "C2", "C3", "E", "VC", "VS", "E-MR", "VS-MR", "VC1-MR", "VC2-MR", "VC3-MR"}) {
        const auto& e = lib.at(name);
        const auto hist = face_size_histogram(e.complex);
        for (int s = 0; s < CubeSymmetry::kOrder; ++s) {
            const auto sym = CubeSymmetry::from_index(s);
            const LatticePoint t{24, -12, 36};
            const auto cx = lib.instance(name, sym, t);
            const auto v = validate(cx, ValidationOptions{.interior_filter = {}, .check_interior = false});
            EXPECT_TRUE(v.ok()) << name << " " << sym.to_string();
            EXPECT_EQ(face_size_histogram(cx), hist) << name << " " << sym.to_string();
            const auto box = placed_leaf_box(e.leaf(), sym, t);
            const auto r = check_element(cx, box, e.cell_labels());
            EXPECT_TRUE(r.ok()) << name << " " << sym.to_string() << "\n" << report(r);
            // and the box is the image of the leaf: a wrong box must fail
            const auto wrong = check_element(cx, ElementBox{t, e.leaf()}, e.cell_labels());
            const bool box_is_t = box.min == t;
            EXPECT_EQ(wrong.ok(), box_is_t) << name << " " << sym.to_string();
        }
    }
}

TEST(SchemesLibrary, InvalidElementIsAHardErrorNamingTheFile) {
    const auto dir = temp_dir("invalid");
    fs::copy_file(elements_dir() / "C1.element", dir / "C1.element");
    auto d = read_element_file(elements_dir() / "F.element");
    d.cells.pop_back();  // drop the lid: the leaf is not filled
    {
        std::ofstream out(dir / "F.element");
        write_element(out, d);
    }
    try {
        (void)ElementLibrary::load(dir);
        ADD_FAILURE() << "accepted";
    } catch (const SchemeFormatError& e) {
        EXPECT_EQ(e.file(), (dir / "F.element").string());
        EXPECT_NE(e.message().find("invalid"), std::string::npos) << e.what();
        EXPECT_NE(e.message().find("LeafUnderfilled"), std::string::npos) << e.what();
    }
    // scan keeps going and reports each file
    const auto scan = scan_elements(dir);
    ASSERT_EQ(scan.size(), 2u);
    EXPECT_TRUE(scan[0].element && scan[0].element->valid());
    EXPECT_TRUE(scan[1].element && !scan[1].element->valid());
    fs::remove_all(dir);
}

TEST(SchemesLibrary, MalformedFileAndNameMismatchAreErrors) {
    const auto dir = temp_dir("malformed");
    {
        std::ofstream out(dir / "X.element");
        out << "dualhex-element 1\nname X\nleaf 2\nvertex 0 0 0 9\n";
    }
    try {
        (void)ElementLibrary::load(dir);
        ADD_FAILURE() << "accepted";
    } catch (const SchemeFormatError& e) {
        EXPECT_EQ(e.file(), (dir / "X.element").string());
        EXPECT_EQ(e.line(), 4) << e.what();
        EXPECT_NE(e.message().find("coordinate 9 outside"), std::string::npos) << e.what();
    }
    const auto scan = scan_elements(dir);
    ASSERT_EQ(scan.size(), 1u);
    EXPECT_FALSE(scan[0].element);
    EXPECT_FALSE(scan[0].error.empty());
    fs::remove_all(dir);

    const auto dir2 = temp_dir("renamed");
    fs::copy_file(elements_dir() / "F.element", dir2 / "G.element");
    try {
        (void)ElementLibrary::load(dir2);
        ADD_FAILURE() << "accepted";
    } catch (const SchemeFormatError& e) {
        EXPECT_NE(e.message().find("differs from the file name 'G'"), std::string::npos) << e.what();
    }
    fs::remove_all(dir2);
}

TEST(SchemesLibrary, DefaultDirectory) {
    ::unsetenv("DUALHEX_ELEMENTS");
    EXPECT_TRUE(fs::equivalent(default_elements_directory(), elements_dir()));
    EXPECT_TRUE(fs::equivalent(source_elements_directory(), elements_dir()));
    const auto dir = temp_dir("env");
    ::setenv("DUALHEX_ELEMENTS", dir.c_str(), 1);
    EXPECT_EQ(default_elements_directory(), dir);
    EXPECT_TRUE(ElementLibrary::load_default().elements().empty());
    ::setenv("DUALHEX_ELEMENTS", (dir / "missing").c_str(), 1);
    EXPECT_THROW((void)default_elements_directory(), SchemeFormatError);
    ::unsetenv("DUALHEX_ELEMENTS");
    fs::remove_all(dir);
}

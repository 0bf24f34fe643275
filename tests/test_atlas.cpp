// The atlas's pages as data: scenes consistent with their complexes, every cell of an
// installed configuration traced to its leaf and element label, tables equal to the
// checkers' reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <fstream>
#include <set>

#include "dualhex/atlas/pages.hpp"
#include "dualhex/atlas/scene.hpp"
#include "dualhex/atlas/site.hpp"
#include "dualhex/checkers/cube_window.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/topology/histograms.hpp"

namespace dualhex::atlas {
namespace {

const ElementLibrary& library() {
    static const ElementLibrary lib = ElementLibrary::load_default();
    return lib;
}

const std::vector<Page>& pages() {
    static const std::vector<Page> all = all_pages(library());
    return all;
}

/// {key: value} of a page's table.
std::map<std::string, nlohmann::json> rows_of(const Page& page, const std::string& table) {
    std::map<std::string, nlohmann::json> out;
    for (const auto& t : page.data["tables"])
        if (t["id"] == table)
            for (const auto& r : t["rows"]) out[r[0].is_string() ? r[0].get<std::string>() : r[0].dump()] = r[1];
    return out;
}

TEST(AtlasRoles, LabelsOfTheElementFiles) {
    EXPECT_EQ(role_of_label("lid"), "lid");
    EXPECT_EQ(role_of_label("lid_corner_1"), "corner");
    EXPECT_EQ(role_of_label("bend_0_corner"), "corner");
    EXPECT_EQ(role_of_label("bend_2"), "bend");
    EXPECT_EQ(role_of_label("tet1"), "bend");
    EXPECT_EQ(role_of_label("rest"), "rest");
    for (const char* chain : {"p1", "p2", "q", "P1", "P1b", "B", "C", "p1c"}) EXPECT_EQ(role_of_label(chain), "chain");
}

TEST(AtlasPages, OnePagePerElementTransitionWeakClassAndVariant) {
    std::map<std::string, int> kinds;
    std::set<std::string> ids;
    for (const auto& p : pages()) {
        ++kinds[p.data["kind"].get<std::string>()];
        EXPECT_TRUE(ids.insert(p.id).second) << p.id;
    }
    EXPECT_EQ(kinds["element"], int(library().elements().size()));
    EXPECT_EQ(kinds["transition"], 20);
    EXPECT_EQ(kinds["weak"], 14);
    EXPECT_EQ(kinds["variant"], 14);
}

TEST(AtlasScene, ReferencesAreInRangeAndRolesKnown) {
    const std::set<std::string> roles{"chain", "bend", "lid", "corner", "rest", "hex", "fine"};
    for (const auto& p : pages()) {
        const auto& s = p.data["scene"];
        const std::size_t nv = s["vertices"].size(), nf = s["faces"].size();
        for (const auto& f : s["faces"]) {
            EXPECT_GE(f.size(), 3u) << p.id;
            for (const auto& v : f) EXPECT_LT(v.get<std::size_t>(), nv) << p.id;
        }
        for (const auto& c : s["cells"]) {
            EXPECT_TRUE(roles.count(c["role"])) << p.id << " " << c["role"];
            EXPECT_NE(c["label"], "?") << p.id << ": a cell not traced to its element's label";
            for (const auto& h : c["faces"]) EXPECT_LT(h[0].get<std::size_t>(), nf) << p.id;
        }
        const std::size_t np = s["dual"]["points"].size();
        EXPECT_GT(s["dual"]["hexes"].size(), 0u) << p.id;
        for (const auto& hex : s["dual"]["hexes"])
            for (const auto& q : hex) EXPECT_LT(q.get<std::size_t>(), np) << p.id;
    }
}

TEST(AtlasScene, ElementPagesShowTheElementsFaces) {
    for (const auto& e : library().elements()) {
        const auto it = std::find_if(pages().begin(), pages().end(), [&](const Page& p) { return p.id == element_page_id(e.name); });
        ASSERT_NE(it, pages().end()) << e.name;
        auto faces = rows_of(*it, "face_sizes");
        for (const auto& [k, n] : face_size_histogram(e.complex)) EXPECT_EQ(faces[std::to_string(k)], n) << e.name;
        // the clipped dual's interior edge valences are the face sizes (clipped_dual.hpp)
        for (const auto& [k, n] : rows_of(*it, "dual_valences")) EXPECT_EQ(faces[k], n) << e.name << " valence " << k;
        EXPECT_EQ(it->data["scene"]["dual"]["hexes"].size(), e.complex.n_vertices()) << e.name;
    }
}

TEST(AtlasScene, ConfigurationCellsTraceEveryCellToOneLeaf) {
    const StrongRule rule;
    for (std::uint8_t mask : {std::uint8_t(1), std::uint8_t(3), std::uint8_t(0x7f)}) {
        const auto built = build_cube_window(mask, rule, library());
        const auto cells = configuration_cells(built, library(), [&](const PlacedLeaf& l) {
            return LeafBox{l.leaf * built.unit, built.unit};
        });
        std::map<std::string, std::size_t> placed;  // cells per element, from the placements
        for (const auto& leaf : built.coarse_leaves)
            placed[leaf.placement ? leaf.placement->element : "hex"] +=
                leaf.placement ? library().at(leaf.placement->element).complex.n_cells() : 1;
        placed["fine"] = built.fine_hexes;
        std::map<std::string, std::size_t> traced;
        for (const auto& c : cells) ++traced[c.element];
        EXPECT_EQ(traced, placed) << int(mask);
    }
}

TEST(AtlasPages, TransitionTablesAreTheWindowReport) {
    for (const auto& p : pages()) {
        if (p.data["kind"] != "transition") continue;
        const int mask = std::stoi(p.id.substr(std::string("transition-").size()));
        const auto report = check_cube_window(std::uint8_t(mask), StrongRule(), library());
        EXPECT_TRUE(report.ok()) << p.id;
        EXPECT_EQ(rows_of(p, "counts")["dual hexes"], report.hexes) << p.id;
        EXPECT_EQ(p.data["scene"]["dual"]["hexes"].size(), report.hexes) << p.id;
        for (const auto& [k, n] : report.dual_edge_valences) EXPECT_EQ(rows_of(p, "dual_valences")[std::to_string(k)], n);
        EXPECT_EQ(rows_of(p, "leaves_at_p").size() + std::popcount(unsigned(mask)), 8u) << p.id;
    }
}

TEST(AtlasSite, RefusesANonEmptyDirectoryWithoutForce) {
    const auto dir = std::filesystem::temp_directory_path() / "dualhex-atlas-test-refuse";
    std::filesystem::remove_all(dir);
    EXPECT_NO_THROW(check_output_directory(dir, false));  // absent
    std::filesystem::create_directories(dir);
    EXPECT_NO_THROW(check_output_directory(dir, false));  // empty
    std::ofstream(dir / "mine.txt") << "user data";
    EXPECT_THROW(check_output_directory(dir, false), SiteError);
    EXPECT_NO_THROW(check_output_directory(dir, true));
    EXPECT_THROW(check_output_directory(dir / "mine.txt", true), SiteError);  // not a directory
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace dualhex::atlas

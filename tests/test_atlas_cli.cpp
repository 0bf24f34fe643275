// dualhex atlas as a process: nothing the user has is overwritten without --force, and
// the site's pages carry the counts the other subcommands print with --json.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_process.hpp"

namespace dualhex::test {
namespace {
namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("dualhex-atlas-cli-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

nlohmann::json run_json(const std::vector<std::string>& args, const fs::path& dir) {
    auto with_json = args;
    with_json.push_back("--json");
    const auto r = run_process(DUALHEX_EXE, with_json, dir);
    EXPECT_EQ(r.rc, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

/// The JSON embedded in a page (<script type="application/json" id="atlas-data">).
nlohmann::json embedded(const fs::path& page) {
    const std::string html = slurp(page), open = "<script type=\"application/json\" id=\"atlas-data\">";
    const auto from = html.find(open);
    EXPECT_NE(from, std::string::npos) << page;
    const auto begin = from + open.size();
    return nlohmann::json::parse(html.substr(begin, html.find("</script>", begin) - begin));
}

/// {key: value} of a table of a page.
std::map<std::string, nlohmann::json> rows_of(const nlohmann::json& page, const std::string& table) {
    std::map<std::string, nlohmann::json> out;
    for (const auto& t : page["tables"])
        if (t["id"] == table)
            for (const auto& r : t["rows"])
                if (!r[1].is_number() || r[1] != 0 || table != "face_sizes")  // the paper's zero columns
                    out[r[0].is_string() ? r[0].get<std::string>() : r[0].dump()] = r[1];
    return out;
}

std::map<std::string, nlohmann::json> as_map(const nlohmann::json& object) {
    std::map<std::string, nlohmann::json> out;
    for (const auto& [k, v] : object.items()) out[k] = v;
    return out;
}

TEST(AtlasCli, RefusesANonEmptyDirectoryAndAFile) {
    const fs::path dir = scratch("refuse");
    fs::create_directories(dir / "site");
    std::ofstream(dir / "site" / "index.html") << "mine";
    auto r = run_process(DUALHEX_EXE, {"atlas", "-o", (dir / "site").string()}, dir);
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir / "site" / "index.html"), "mine");
    std::ofstream(dir / "file") << "mine";
    r = run_process(DUALHEX_EXE, {"atlas", "-o", (dir / "file").string(), "--force"}, dir);
    EXPECT_EQ(r.rc, 2);
    EXPECT_EQ(slurp(dir / "file"), "mine");
    r = run_process(DUALHEX_EXE, {"atlas"}, dir);  // -o is required
    EXPECT_EQ(r.rc, 2);
    fs::remove_all(dir);
}

TEST(AtlasCli, EveryPageShowsTheCountsOfTheOtherCommands) {
    const fs::path dir = scratch("site");
    const auto summary = run_json({"atlas", "-o", (dir / "site").string()}, dir);
    std::map<std::string, nlohmann::json> pages;
    for (const auto& p : summary["pages"]) {
        ASSERT_TRUE(fs::exists(dir / "site" / (p["id"].get<std::string>() + ".html"))) << p["id"];
        pages[p["id"]] = embedded(dir / "site" / (p["id"].get<std::string>() + ".html"));
        EXPECT_EQ(pages[p["id"]]["tables"], p["tables"]) << p["id"];
    }
    EXPECT_TRUE(fs::exists(dir / "site" / "index.html"));
    EXPECT_TRUE(fs::exists(dir / "site" / "assets" / "three.min.js"));

    const auto list = run_json({"element", "--list"}, dir);
    for (const auto& e : list["elements"]) {
        const std::string name = e["name"];
        const auto element = run_json({"element", name}, dir);
        const auto& page = pages.at("element-" + name);
        EXPECT_EQ(rows_of(page, "counts"), as_map(element["counts"])) << name;
        EXPECT_EQ(rows_of(page, "face_sizes"), as_map(element["face_histogram"])) << name;
    }
    const auto variants = run_json({"variants"}, dir);
    for (const char* region : {"flat", "concave_edge", "concave_corner"})
        for (const auto& v : variants[region]["variants"]) {
            const auto& page = pages.at("variant-" + v["name"].get<std::string>());
            EXPECT_EQ(rows_of(page, "face_sizes"), as_map(v["element_faces"])) << v["name"];
            EXPECT_EQ(rows_of(page, "bend_faces"), as_map(v["bend_faces"])) << v["name"];
            EXPECT_EQ(rows_of(page, "dual_valences"), as_map(v["dual_edge_valences"])) << v["name"];
        }
    const auto table = run_json({"table"}, dir);
    EXPECT_EQ(table["classes"].size(), 20u);
    for (const auto& c : table["classes"]) {
        const auto& page = pages.at("transition-" + std::to_string(c["representative"].get<int>()));
        std::map<std::string, nlohmann::json> leaves;
        for (const auto& l : c["leaves"]) leaves[l["position"]] = l["element"];
        EXPECT_EQ(rows_of(page, "leaves_at_p"), leaves) << c["representative"];
    }
    // --force writes into the non-empty directory and leaves the user's other files alone
    std::ofstream(dir / "site" / "notes.txt") << "mine";
    EXPECT_EQ(run_process(DUALHEX_EXE, {"atlas", "-o", (dir / "site").string(), "--force"}, dir).rc, 0);
    EXPECT_EQ(slurp(dir / "site" / "notes.txt"), "mine");
    fs::remove_all(dir);
}

}  // namespace
}  // namespace dualhex::test

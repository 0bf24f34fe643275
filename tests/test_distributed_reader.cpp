// dualhex-dist's partitioned leaf reader (distributed/src/leaf_reader.hpp) under mpirun:
// a shuffled file with comments and blank lines gives the serial summary on 1-4 ranks
// while each rank reads about 1/np of the bytes and parses about 1/np of the lines; every
// fault (bad line, deep level, duplicate, overlap, gap, empty file) is refused with exit 3
// and the same located message (file:line) on any rank count, wherever in the file it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>

#include <nlohmann/json.hpp>

#include "dualhex/distributed/canonical_json.hpp"
#include "test_distributed_fixture.hpp"
#include "test_distributed_run.hpp"

namespace dualhex {
namespace {

namespace fs = std::filesystem;

// The grid's leaves as lines, shuffled, with comments and blank lines between.
std::vector<std::string> shuffled_lines(const LeafGrid& grid, unsigned seed) {
    std::vector<std::string> lines;
    for (const Leaf& l : grid.leaves()) lines.push_back(to_string(l));
    std::mt19937 rng(seed);
    std::shuffle(lines.begin(), lines.end(), rng);
    for (std::size_t n = 0; n < lines.size(); n += 97) lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(n), n % 2 ? "" : "# a comment");
    lines.back() += "  # after a leaf";
    return lines;
}

void write_lines(const fs::path& file, const std::vector<std::string>& lines, bool final_newline = true) {
    std::ofstream out(file, std::ios::binary);
    for (std::size_t n = 0; n < lines.size(); ++n) out << lines[n] << (n + 1 < lines.size() || final_newline ? "\n" : "");
}

nlohmann::json run_json(int np, const fs::path& file, const fs::path& scratch) {
    const auto r = test::run_dist(np, {file.string(), "--balance", "strong", "--json"}, scratch);
    EXPECT_EQ(r.rc, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

TEST(DistributedReader, ShuffledFileMatchesSerialWithEachRankReadingItsShare) {
    test::Scratch s("reader");
    const LeafGrid grid = read_leaf_file(fs::path(DUALHEX_SHARED_DATA) / "grids" / "sphere_strong_d5.leaves");
    const fs::path file = s.dir / "shuffled.leaves";
    write_lines(file, shuffled_lines(grid, 7), false);  // no final newline: the last line still counts
    const std::uint64_t bytes = fs::file_size(file);
    const CanonicalSummary serial = test::serial_summary(read_leaf_file(file), Balance::Strong);
    for (int np : {1, 2, 3, 4}) {
        const nlohmann::json doc = run_json(np, file, s.dir);
        EXPECT_EQ(to_json(summary_from_json(doc["summary"])), to_json(serial)) << "np " << np;
        std::uint64_t parsed = 0, sorted = 0;
        for (const auto& r : doc["per_rank"]) {
            const auto& in = r["input"];
            // Its range, give or take a line, and two 128-byte probes for the line starts.
            EXPECT_LE(in["bytes_read"].get<std::uint64_t>(), bytes / static_cast<std::uint64_t>(np) + 300) << "np " << np;
            EXPECT_GE(in["leaves_parsed"].get<std::uint64_t>(), grid.size() / static_cast<std::size_t>(np) * 9 / 10);
            parsed += in["leaves_parsed"].get<std::uint64_t>();
            sorted += in["leaves_sorted"].get<std::uint64_t>();
            if (np > 1) {
                EXPECT_LT(in["leaves_sorted"].get<std::uint64_t>(), grid.size() * 3 / 4) << "the sort spreads the leaves";
            }
        }
        EXPECT_EQ(parsed, grid.size());
        EXPECT_EQ(sorted, grid.size());
    }
}

// Exit 3 on each rank count, the same error line on all; returns it.
std::string refused(const fs::path& file, const fs::path& scratch, std::vector<int> nps = {3}) {
    std::string first;
    for (int np : nps) {
        const auto r = test::run_dist(np, {file.string()}, scratch);
        EXPECT_EQ(r.rc, 3) << file << " np " << np << ": " << r.err;
        const std::string line = r.err.substr(0, r.err.find('\n'));  // mpirun adds its own lines
        if (first.empty()) {
            first = line;
        } else {
            EXPECT_EQ(line, first) << "np " << np;
        }
    }
    return first;
}

TEST(DistributedReader, FaultsAreLocatedWhereverTheyAre) {
    test::Scratch s("reader_bad");
    // 64 level-2 leaves of a uniform grid; each fault put near the end (the last rank's range).
    std::vector<std::string> base;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) base.push_back(to_string(Leaf{2, i, j, k}));
    const auto with = [&](const char* name, auto change, std::vector<int> nps = {3}) {
        std::vector<std::string> lines = base;
        change(lines);
        const fs::path file = s.dir / name;
        write_lines(file, lines);
        return refused(file, s.dir, nps);
    };
    std::string e = with("syntax.leaves", [](auto& l) { l[60] = "2 1 x 0"; }, {1, 4});
    EXPECT_NE(e.find("syntax.leaves:61: not an integer: 'x'"), std::string::npos) << e;
    e = with("deep.leaves", [](auto& l) { l[59] = "19 0 0 0"; });
    EXPECT_NE(e.find("deep.leaves:60: leaf 19 0 0 0: level 19 is beyond p8est's 18"), std::string::npos) << e;
    e = with("duplicate.leaves", [](auto& l) { l.push_back(l[3]); });
    EXPECT_NE(e.find("duplicate.leaves:65: duplicate leaf " + base[3] + " (line 65), first given as " + base[3] + " (line 4)"),
              std::string::npos) << e;
    e = with("overlap.leaves", [](auto& l) { l.push_back("3 7 7 7"); });
    EXPECT_NE(e.find("overlap.leaves:65: overlap: leaf 3 7 7 7 (line 65) lies inside leaf 2 3 3 3 (line 64)"), std::string::npos) << e;
    e = with("gap.leaves", [](auto& l) { l.erase(l.begin() + 62); });  // 2 3 3 2
    EXPECT_NE(e.find("gap.leaves: gap: cell 2 3 3 2 (level 2) is not covered by any leaf"), std::string::npos) << e;
    e = with("gap_first.leaves", [](auto& l) { l.erase(l.begin()); });  // 2 0 0 0
    EXPECT_NE(e.find("gap: cell 2 0 0 0 (level 2)"), std::string::npos) << e;
    e = with("gap_last.leaves", [](auto& l) { l.pop_back(); });  // 2 3 3 3
    EXPECT_NE(e.find("gap: cell 2 3 3 3 (level 2)"), std::string::npos) << e;
    e = with("empty.leaves", [](auto& l) { l = {"# nothing", ""}; });
    EXPECT_NE(e.find("gap: no leaves"), std::string::npos) << e;
    e = refused(s.dir / "missing.leaves", s.dir, {2});
    EXPECT_NE(e.find("missing.leaves: cannot open leaf file"), std::string::npos) << e;
    // A located fault beats a gap, whichever rank sees which.
    e = with("both.leaves", [](auto& l) { l.erase(l.begin()); l[62] = "2 3 3 9"; });
    EXPECT_NE(e.find("both.leaves:63: invalid leaf 2 3 3 9"), std::string::npos) << e;
}

}  // namespace
}  // namespace dualhex

// Leaf-file I/O: round trips, and each kind of bad file giving its documented message.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "dualhex/grid/input_error.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/grid/refinement.hpp"
#include "scratch_dir.hpp"

using namespace dualhex;
namespace fs = std::filesystem;

namespace {

class LeafFile : public test::ScratchDirTest {
protected:
    LeafFile() : ScratchDirTest("dualhex_grid_test_") {}
    fs::path write_file(const std::string& name, const std::string& text) const {
        const fs::path path = dir_ / name;
        std::ofstream(path) << text;
        return path;
    }
};

// The 8 children of the root, as leaf-file lines (a valid tiling).
const std::string kEight = "1 0 0 0\n1 1 0 0\n1 0 1 0\n1 1 1 0\n1 0 0 1\n1 1 0 1\n1 0 1 1\n1 1 1 1\n";

struct BadFile {
    const char* name;
    std::string text;
    int line;                   // expected InputError::line()
    std::vector<std::string> mentions;  // substrings the message must contain
};

}  // namespace

TEST_F(LeafFile, RoundTripThroughDisk) {
    const LeafGrid g = pair(parse_leaves("# a comment\n\n0 0 0 0   # the root\n"), Balance::Strong);
    const LeafGrid refined = balance(parse_leaves(kEight), Balance::Strong);
    const fs::path path = dir_ / "roundtrip.leaves";
    write_leaf_file(refined, path, "made by a test\nsecond header line");
    const LeafGrid back = read_leaf_file(path);
    EXPECT_EQ(back.leaves(), refined.leaves());
    EXPECT_EQ(back.line(0), 3);  // two header comment lines first
    EXPECT_EQ(back.source(), path.string());
    EXPECT_EQ(format_leaves(back), format_leaves(refined));
    EXPECT_EQ(g.size(), 1u);
}

TEST_F(LeafFile, CommentsBlankLinesAndWhitespace) {
    const LeafGrid g = parse_leaves("# header\n\n\t1 0 0 0 # trailing\n1 1 0 0\r\n1 0 1 0\n1 1 1 0\n 1 0 0 1\n1 1 0 1\n"
                                    "1 0 1 1\n1   1 1 1\n# end",
                                    "x.leaves");
    ASSERT_EQ(g.size(), 8u);
    EXPECT_EQ(g.line(0), 3);
    EXPECT_EQ(g.describe(0), "1 0 0 0 (line 3)");
    EXPECT_EQ(g.counts_per_level(), (std::vector<std::size_t>{0, 8}));
}

TEST_F(LeafFile, BadFilesNameLineAndEntity) {
    const std::vector<BadFile> cases = {
        {"bad_token.leaves", "1 0 0 0\n1 x 0 0\n", 2, {"bad_token.leaves:2", "not an integer: 'x'", "'1 x 0 0'"}},
        {"float.leaves", "1 0.5 0 0\n", 1, {"not an integer: '0.5'"}},
        {"missing.leaves", "# c\n1 0 0\n", 2, {"missing.leaves:2", "expected 4 fields", "found 3", "'1 0 0'"}},
        {"extra.leaves", "1 0 0 0 7\n", 1, {"expected 4 fields", "found 5", "'1 0 0 0 7'"}},
        {"neg_level.leaves", "-1 0 0 0\n", 1, {"invalid leaf '-1 0 0 0'", "level -1 must be in [0, 30]"}},
        {"deep_level.leaves", "31 0 0 0\n", 1, {"level 31 must be in [0, 30]"}},
        {"out_of_range.leaves", kEight + "2 4 0 0\n", 9, {"invalid leaf 2 4 0 0", "[0, 2^2)"}},
        {"negative.leaves", "1 0 -1 0\n", 1, {"invalid leaf 1 0 -1 0", "[0, 2^1)"}},
        {"huge.leaves", "1 0 99999999999999999999 0\n", 1, {"integer out of range"}},
        {"duplicate.leaves", kEight + "# again\n1 1 0 1\n", 10,
         {"duplicate leaf 1 1 0 1 (line 10)", "first given as 1 1 0 1 (line 6)"}},
        {"overlap.leaves", kEight + "2 1 1 1\n", 9,
         {"overlap: leaf 2 1 1 1 (line 9) lies inside leaf 1 0 0 0 (line 1)"}},
        {"overlap_root.leaves", "0 0 0 0\n" + kEight, 2, {"overlap", "inside leaf 0 0 0 0 (line 1)"}},
        {"gap.leaves", "1 0 0 0\n1 1 0 0\n1 0 1 0\n1 1 1 0\n1 0 0 1\n1 1 0 1\n1 0 1 1\n", 0,
         {"gap.leaves: gap", "cell 1 1 1 1", "not covered"}},
        {"empty.leaves", "# nothing here\n\n", 0, {"gap: no leaves", "root cube 0 0 0 0"}},
        // Levels mixed so that the volume is wrong: 7 level-1 leaves and 7 level-2 ones.
        {"mixed_gap.leaves",
         "1 1 0 0\n1 0 1 0\n1 1 1 0\n1 0 0 1\n1 1 0 1\n1 0 1 1\n1 1 1 1\n2 1 0 0\n2 0 1 0\n2 1 1 0\n2 0 0 1\n2 1 0 1\n"
         "2 0 1 1\n2 1 1 1\n",
         0, {"gap: cell 2 0 0 0 (level 2) is not covered"}},
    };
    for (const BadFile& bad : cases) {
        const fs::path path = write_file(bad.name, bad.text);
        try {
            (void)read_leaf_file(path);
            ADD_FAILURE() << bad.name << ": accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(e.line(), bad.line) << bad.name << ": " << e.what();
            EXPECT_EQ(e.file(), path.string()) << bad.name;
            const std::string what = e.what();
            for (const std::string& m : bad.mentions)
                EXPECT_NE(what.find(m), std::string::npos) << bad.name << ": '" << m << "' not in: " << what;
        }
    }
}

TEST_F(LeafFile, MissingFileIsAnInputError) {
    EXPECT_THROW((void)read_leaf_file(dir_ / "does_not_exist.leaves"), InputError);
}

TEST_F(LeafFile, Reads172kLeavesQuickly) {
    const fs::path path = fs::path(DUALHEX_SHARED_DATA) / "grids" / "sphere_strong_d7.leaves";
    const auto start = std::chrono::steady_clock::now();
    const LeafGrid g = read_leaf_file(path);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(g.size(), 172096u);
    EXPECT_EQ(g.line(0), 3);
    // Informational: the unit suite asserts no timing (shared machine); see bench/.
    std::cout << "read " << g.size() << " leaves in " << seconds << " s\n";
}

TEST_F(LeafFile, PredicateDiagnosticsNameFileAndLines) {
    // 1 0 0 0 refined twice at the root centre: 3 3 3 3 shares a face with level-1 leaves.
    std::string text = "1 1 0 0\n1 0 1 0\n1 1 1 0\n1 0 0 1\n1 1 0 1\n1 0 1 1\n1 1 1 1\n";
    for (const char* l2 : {"2 0 0 0", "2 1 0 0", "2 0 1 0", "2 1 1 0", "2 0 0 1", "2 1 0 1", "2 0 1 1"})
        text += std::string(l2) + "\n";
    for (int c = 0; c < 8; ++c)
        text += "3 " + std::to_string(2 + (c & 1)) + " " + std::to_string(2 + (c >> 1 & 1)) + " " +
                std::to_string(2 + (c >> 2 & 1)) + "\n";
    const LeafGrid g = read_leaf_file(write_file("unbalanced.leaves", text));
    const auto check = is_weakly_balanced(g);
    ASSERT_FALSE(check.ok);
    EXPECT_NE(check.message.find("unbalanced.leaves: not weakly balanced: leaves 3 3 "), std::string::npos)
        << check.message;
    EXPECT_NE(check.message.find("(line 1"), std::string::npos) << check.message;
    EXPECT_NE(check.message.find("share a face but differ by 2 levels"), std::string::npos) << check.message;
    const auto paired = is_paired(g);  // the level-1 leaves' sibling 1 0 0 0 is subdivided
    ASSERT_FALSE(paired.ok);
    EXPECT_NE(paired.message.find("not paired: leaf 1 1 0 0 (line 1) has sibling 1 0 0 0 subdivided"),
              std::string::npos)
        << paired.message;
}

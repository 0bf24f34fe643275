// Runs the built `dualhex` binary (DUALHEX_EXE) as a process and checks its contract:
// --help everywhere, JSON output, exit codes (README "Exit codes"), no silent overwrite.
#include <gtest/gtest.h>

#include "run_process.hpp"
#include "scratch_dir.hpp"
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <bit>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Result = dualhex::test::ProcessResult;
using dualhex::test::slurp;

class Cli : public dualhex::test::ScratchDirTest {
protected:
    Cli() : ScratchDirTest("dualhex_cli_") {}

    Result run(const std::vector<std::string>& args) const { return dualhex::test::run_process(DUALHEX_EXE, args, dir_); }

    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p;
    }

};

TEST_F(Cli, HelpOfEverySubcommand) {
    const std::vector<std::vector<std::string>> cmds = {
        {}, {"classify"}, {"element"}, {"grid"}, {"grid", "check"}, {"grid", "balance"}, {"grid", "pair"}, {"verify"}};
    for (auto args : cmds) {
        args.push_back("--help");
        const Result r = run(args);
        EXPECT_EQ(r.rc, 0) << r.err;
        EXPECT_NE(r.out.find("Usage:"), std::string::npos) << r.out;
        if ((args.size() > 1 && args[0] != "grid") || args.size() > 2) {
            EXPECT_NE(r.out.find("--json"), std::string::npos) << "no --json in help of " << args[0];
        }
    }
}

TEST_F(Cli, ClassifyJsonMatchesThePaper) {
    const Result r = run({"classify", "--json"});
    ASSERT_EQ(r.rc, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);  // stdout is nothing but JSON
    EXPECT_EQ(j.at("classes_full_group").get<int>(), 22);
    EXPECT_EQ(j.at("classes_rotations").get<int>(), 23);
    EXPECT_EQ(j.at("nontrivial_classes").get<int>(), 20);
    EXPECT_TRUE(j.at("matches_paper").get<bool>());
    const auto& classes = j.at("classes");
    ASSERT_EQ(classes.size(), 22u);
    int total = 0;
    std::set<int> reps;
    for (const auto& c : classes) {
        const int rep = c.at("representative").get<int>();
        ASSERT_GE(rep, 0);
        ASSERT_LT(rep, 256);
        reps.insert(rep);
        total += c.at("size").get<int>();
        EXPECT_EQ(c.at("fine_octants").get<int>(), std::popcount(static_cast<unsigned>(rep)));
    }
    EXPECT_EQ(reps.size(), 22u);
    EXPECT_EQ(total, 256);
}

TEST_F(Cli, VerifyJsonListsChecksAndPasses) {
    const Result r = run({"verify", "--json"});
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(r.rc, j.at("ok").get<bool>() ? 0 : 1);
    EXPECT_TRUE(j.at("ok").get<bool>()) << r.out;
    bool saw_symmetry = false;
    for (const auto& c : j.at("checks")) {
        EXPECT_TRUE(c.contains("name") && c.contains("status") && c.contains("ok"));
        if (c.at("name") == "symmetry.group") saw_symmetry = c.at("status") == "PASS";
    }
    EXPECT_TRUE(saw_symmetry) << r.out;
    // the issues' summary blocks, with computed numbers
    const auto& strong = j.at("strong");
    EXPECT_EQ(strong.at("configurations").get<int>(), 256);
    EXPECT_EQ(strong.at("passed").get<int>(), 256);
    EXPECT_EQ(strong.at("classes").get<int>(), 20);
    EXPECT_EQ(strong.at("max_dual_edge_valence").get<int>(), 6);
    EXPECT_EQ(strong.at("elements").size(), 8u);
    EXPECT_EQ(strong.at("elements").at("F").at("F3").get<int>(), 5);
    const auto& weak = j.at("weak");
    EXPECT_EQ(weak.at("configurations").get<int>(), 487);
    EXPECT_EQ(weak.at("passed").get<int>(), 487);
    EXPECT_EQ(weak.at("classes").get<int>(), 14);
    EXPECT_EQ(weak.at("max_dual_edge_valence").get<int>(), 7);
    EXPECT_EQ(weak.at("elements").size(), 5u);
}

TEST_F(Cli, TableShowsTheTwentyTransitions) {
    const Result r = run({"table", "--json"});
    ASSERT_EQ(r.rc, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("transitions").get<int>(), 20);
    ASSERT_EQ(j.at("classes").size(), 20u);
    int coarse_leaves = 0;
    for (const auto& c : j.at("classes")) {
        // one entry per coarse octant around the application point
        EXPECT_EQ(static_cast<int>(c.at("leaves").size()), 8 - c.at("fine_octants").get<int>());
        coarse_leaves += static_cast<int>(c.at("leaves").size());
    }
    EXPECT_GT(coarse_leaves, 0);
    // the periodic embedding uses every strong element but VS (which needs the reach)
    const auto& use = j.at("element_use");
    for (const char* e : {"F", "F+C", "C1", "C2", "C3", "E", "VC"}) EXPECT_TRUE(use.contains(e)) << e;
    EXPECT_FALSE(use.contains("VS"));
}

TEST_F(Cli, VerifyOnlyAndList) {
    const Result list = run({"verify", "--list", "--json"});
    ASSERT_EQ(list.rc, 0) << list.err;
    const auto checks = nlohmann::json::parse(list.out).at("checks");
    ASSERT_GE(checks.size(), 4u);
    std::size_t on_request = 0;
    for (const auto& c : checks) {
        const auto name = c.at("name").get<std::string>();
        if (c.at("on_request").get<bool>()) {  // long exhaustive runs: listed, not run here (nor by default)
            ++on_request;
            continue;
        }
        const Result one = run({"verify", "--json", "--only", name});
        ASSERT_EQ(one.rc, 0) << name << ": " << one.out << one.err;
        const auto j = nlohmann::json::parse(one.out);
        EXPECT_GE(j.at("checks").size(), 1u);
        EXPECT_EQ(j.at("failed").get<int>(), 0);
    }
    EXPECT_EQ(on_request, 2u);  // proofs.weak_stars, proofs.weak_near_root_surface
    // a substring of their names selects the other checks only
    const auto some = nlohmann::json::parse(run({"verify", "--list", "--json", "--only", "proofs.weak"}).out).at("checks");
    std::size_t long_ones = 0;
    for (const auto& c : some) long_ones += c.at("on_request").get<bool>();
    EXPECT_EQ(long_ones, 0u);
    EXPECT_GE(some.size(), 2u);  // weak_balance, weak_root_boundary
}

TEST_F(Cli, VerifyTableHasSummary) {
    const Result r = run({"verify"});
    EXPECT_EQ(r.rc, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("PASS"), std::string::npos);
    EXPECT_NE(r.out.find("passed"), std::string::npos);
    EXPECT_EQ(r.out.find("proofs.weak_stars"), std::string::npos);  // on request only
    EXPECT_EQ(r.out.find("proofs.weak_near_root_surface"), std::string::npos);
}

TEST_F(Cli, BadUsageExits2) {
    const fs::path in = write("in.leaves", "0 0 0 0\n");
    EXPECT_EQ(run({}).rc, 2);
    EXPECT_EQ(run({"no-such-command"}).rc, 2);
    EXPECT_EQ(run({"classify", "--no-such-option"}).rc, 2);
    EXPECT_EQ(run({"grid"}).rc, 2);
    EXPECT_EQ(run({"grid", "check"}).rc, 2);                                    // FILE missing
    EXPECT_EQ(run({"grid", "check", (dir_ / "missing.leaves").string()}).rc, 2);  // no such file
    EXPECT_EQ(run({"grid", "pair", in.string()}).rc, 2);                        // -o missing
    EXPECT_EQ(run({"grid", "balance", in.string(), "-o", (dir_ / "o").string()}).rc, 2);  // no mode
    EXPECT_EQ(run({"grid", "balance", in.string(), "--strong", "--weak", "-o", (dir_ / "o").string()}).rc, 2);
    EXPECT_EQ(run({"verify", "--only", "no-such-check"}).rc, 2);
    const Result r = run({"verify", "--bogus"});
    EXPECT_EQ(r.rc, 2);
    EXPECT_TRUE(r.out.empty()) << r.out;  // errors go to stderr
    EXPECT_FALSE(r.err.empty());
}

TEST_F(Cli, MalformedLeafFileExits3WithFileAndLine) {
    const fs::path bad = write("bad.leaves", "# a comment\n1 0 0 0\n1 0 zero 1\n");
    const Result r = run({"grid", "check", bad.string()});
    EXPECT_EQ(r.rc, 3) << r.err;
    EXPECT_NE(r.err.find("error: " + bad.string() + ":3:"), std::string::npos) << r.err;
}

TEST_F(Cli, RefusesToOverwriteWithoutForce) {
    const fs::path in = write("in.leaves", "0 0 0 0\n");
    for (const std::vector<std::string>& cmd :
         {std::vector<std::string>{"grid", "pair"}, std::vector<std::string>{"grid", "balance", "--strong"}}) {
        const fs::path out = write("out.leaves", "keep me\n");
        auto args = cmd;
        args.insert(args.end(), {in.string(), "-o", out.string()});
        const Result r = run(args);
        EXPECT_EQ(r.rc, 2) << r.err;
        EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
        EXPECT_EQ(slurp(out), "keep me\n");

        args.push_back("--force");
        const Result forced = run(args);
        EXPECT_EQ(forced.rc, 0) << forced.err;
        EXPECT_NE(slurp(out), "keep me\n");
    }
}

/// A level-1 grid with octant 0 refined twice more (level 3): neither paired nor balanced.
std::string unbalanced_grid() {
    std::string text = "# octant 0 refined to level 3\n";
    for (int c = 1; c < 8; ++c)
        text += "1 " + std::to_string(c & 1) + " " + std::to_string((c >> 1) & 1) + " " + std::to_string(c >> 2) + "\n";
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k)
                text += "3 " + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(k) + "\n";
    return text;
}

TEST_F(Cli, GridCheckNamesOffendingLeaves) {
    const fs::path in = write("unbalanced.leaves", unbalanced_grid());
    const Result r = run({"grid", "check", in.string(), "--json"});
    ASSERT_EQ(r.rc, 0) << r.err;  // nothing --require'd
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("leaves").get<int>(), 71);
    EXPECT_EQ(j.at("leaves_per_level"), nlohmann::json::parse("[0, 7, 0, 64]"));
    for (const char* key : {"paired", "strongly_balanced", "weakly_balanced"}) {
        EXPECT_FALSE(j.at(key).at("ok").get<bool>()) << key;
        ASSERT_EQ(j.at(key).at("leaves").size(), 2u) << key;
        // each offending leaf is named "L i j k ..." (plus where it was given), the message names the file
        for (const auto& leaf : j.at(key).at("leaves")) {
            const auto text = leaf.get<std::string>();
            EXPECT_TRUE(text.rfind("1 ", 0) == 0 || text.rfind("3 ", 0) == 0) << text;
        }
        EXPECT_NE(j.at(key).at("message").get<std::string>().find("unbalanced.leaves"), std::string::npos);
    }
    EXPECT_EQ(run({"grid", "check", in.string(), "--require", "weak"}).rc, 1);
}

TEST_F(Cli, GridBalanceAndPairGiveGridsThatCheck) {
    const fs::path in = write("unbalanced.leaves", unbalanced_grid());
    for (const char* mode : {"--strong", "--weak"}) {
        const fs::path balanced = dir_ / (std::string("balanced") + mode + ".leaves");
        const Result b = run({"grid", "balance", in.string(), mode, "-o", balanced.string()});
        ASSERT_EQ(b.rc, 0) << b.err;
        const std::string req = std::string(mode) == "--strong" ? "strong" : "weak";
        EXPECT_EQ(run({"grid", "check", balanced.string(), "--require", req}).rc, 0);

        const fs::path paired = dir_ / (std::string("paired") + mode + ".leaves");
        const Result p = run({"grid", "pair", in.string(), mode, "-o", paired.string(), "--json"});
        ASSERT_EQ(p.rc, 0) << p.err;
        const auto j = nlohmann::json::parse(p.out);
        EXPECT_EQ(j.at("leaves_in").get<int>(), 71);
        EXPECT_GT(j.at("leaves_out").get<int>(), 71);
        EXPECT_EQ(run({"grid", "check", paired.string(), "--require", "paired", "--require", req}).rc, 0);
    }
}

}  // namespace

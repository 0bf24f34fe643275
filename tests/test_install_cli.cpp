// `dualhex install` run as a process (DUALHEX_EXE): a small two-level grid installs and
// verifies, both VTK files parse (POINTS / CELLS / CELL_TYPES counts agree with the JSON),
// a grid that is not strongly balanced is refused as bad input (exit 3) naming leaves,
// existing outputs are not overwritten without --force (exit 2).
#include <gtest/gtest.h>

#include "run_process.hpp"
#include "scratch_dir.hpp"
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Result = dualhex::test::ProcessResult;
using dualhex::test::slurp;

// Level 2 everywhere, the level-1 octant at the origin one level finer: paired, strongly
// balanced, with flat, convex-edge and convex-corner transitions (and root-wall contacts).
std::string two_level_grid() {
    std::ostringstream os;
    os << "# test grid: level 2, octant (0,0,0) of level 1 refined to level 3\n";
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) {
                if (i < 2 && j < 2 && k < 2) {
                    for (int a = 0; a < 2; ++a)
                        for (int b = 0; b < 2; ++b)
                            for (int c = 0; c < 2; ++c) os << "3 " << 2 * i + a << ' ' << 2 * j + b << ' ' << 2 * k + c << '\n';
                } else {
                    os << "2 " << i << ' ' << j << ' ' << k << '\n';
                }
            }
    return os.str();
}

// The VTK legacy sections: POINTS n, CELLS n size (size = number of integers that follow),
// CELL_TYPES n with every type equal to `type`. Returns {points, cells}.
std::pair<long, long> parse_vtk(const fs::path& p, int type) {
    std::ifstream in(p);
    std::string line;
    long points = -1, cells = -1, size = -1;
    std::getline(in, line);
    EXPECT_EQ(line.rfind("# vtk DataFile Version", 0), 0U) << p;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string key;
        ls >> key;
        if (key == "POINTS") {
            ls >> points;
            for (long i = 0; i < points; ++i) {
                double x, y, z;
                in >> x >> y >> z;
                EXPECT_TRUE(x >= 0 && x <= 1 && y >= 0 && y <= 1 && z >= 0 && z <= 1) << p << " point " << i;
            }
        } else if (key == "CELLS") {
            ls >> cells >> size;
            long read = 0;
            for (long c = 0; c < cells; ++c) {
                long n;
                in >> n;
                ++read;
                for (long i = 0; i < n; ++i) {
                    long v;
                    in >> v;
                    ++read;
                    if (type == 12) {
                        EXPECT_GE(v, 0);
                        EXPECT_LT(v, points);
                    }
                }
            }
            EXPECT_EQ(read, size) << p;
        } else if (key == "CELL_TYPES") {
            long n;
            ls >> n;
            EXPECT_EQ(n, cells);
            for (long c = 0; c < n; ++c) {
                int t;
                in >> t;
                EXPECT_EQ(t, type);
            }
        }
    }
    return {points, cells};
}

class InstallCli : public dualhex::test::ScratchDirTest {
protected:
    InstallCli() : ScratchDirTest("dualhex_install_cli_") {}

    Result run(const std::vector<std::string>& args, const std::string& exe = DUALHEX_EXE) const {
        return dualhex::test::run_process(exe, args, dir_);
    }
    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p;
    }
};

TEST_F(InstallCli, SmallGridInstallsAndWritesBothFiles) {
    const fs::path grid = write("g.leaves", two_level_grid());
    const std::string prefix = (dir_ / "out").string();
    for (const char* outside : {"coarse", "mirror"}) {
        const Result r = run({"install", grid.string(), "-o", prefix, "--json", "--force", "--outside-root", outside});
        ASSERT_EQ(r.rc, 0) << r.out << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j.at("leaves").get<int>(), 56 + 64);
        EXPECT_TRUE(j.at("ok").get<bool>()) << r.out;
        EXPECT_GT(j.at("non_hex_cells").get<int>(), 0);
        EXPECT_EQ(j.at("non_cube_dual_cells").get<int>(), 0);
        for (const char* key : {"elements", "face_sizes", "dual_edge_valences", "ms"}) EXPECT_TRUE(j.at(key).is_object()) << key;
        for (const char* key : {"read", "install", "dual", "verify", "write"}) EXPECT_TRUE(j.at("ms").contains(key)) << key;
        EXPECT_TRUE(j.at("elements").contains("F"));
        EXPECT_EQ(j.at("dual_edge_valences"), j.at("face_sizes"));  // clipped dual: all faces are dual edges
        const auto [poly_points, poly_cells] = parse_vtk(prefix + ".poly.vtk", 42);
        const auto [hex_points, hex_cells] = parse_vtk(prefix + ".hex.vtk", 12);
        EXPECT_EQ(poly_points, j.at("vertices").get<long>());
        EXPECT_EQ(poly_cells, j.at("cells").get<long>());
        EXPECT_EQ(hex_cells, j.at("hexes").get<long>());
        EXPECT_EQ(hex_cells, poly_points);  // one hex per primal vertex
        EXPECT_EQ(hex_points, j.at("dual_points").get<long>());
    }
    // Text output names the figures.
    const Result text = run({"install", grid.string(), "-o", prefix, "--force"});
    EXPECT_EQ(text.rc, 0) << text.err;
    EXPECT_NE(text.out.find("interior dual edge valences"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("OK"), std::string::npos) << text.out;
}

TEST_F(InstallCli, RefusesOverwriteWithoutForce) {
    const fs::path grid = write("g.leaves", two_level_grid());
    const std::string prefix = (dir_ / "out").string();
    write("out.hex.vtk", "keep me");
    const Result r = run({"install", grid.string(), "-o", prefix});
    EXPECT_EQ(r.rc, 2) << r.err;
    EXPECT_EQ(slurp(dir_ / "out.hex.vtk"), "keep me");
    EXPECT_FALSE(fs::exists(dir_ / "out.poly.vtk"));
}

TEST_F(InstallCli, UnpairedGridIsBadInputNamingLeaves) {
    // Root split once; leaf (1,0,0,0) split twice down to level 3 in one corner: the
    // level-2 leaves beside the split one are not paired.
    std::ostringstream os;
    for (int c = 1; c < 8; ++c) os << "1 " << (c & 1) << ' ' << (c >> 1 & 1) << ' ' << (c >> 2 & 1) << '\n';
    for (int c = 1; c < 8; ++c) os << "2 " << (c & 1) << ' ' << (c >> 1 & 1) << ' ' << (c >> 2 & 1) << '\n';
    for (int c = 0; c < 8; ++c) os << "3 " << (c & 1) << ' ' << (c >> 1 & 1) << ' ' << (c >> 2 & 1) << '\n';
    const fs::path grid = write("bad.leaves", os.str());
    const Result r = run({"install", grid.string(), "-o", (dir_ / "out").string()});
    EXPECT_EQ(r.rc, 3) << r.out << r.err;
    EXPECT_NE(r.err.find("line"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.poly.vtk"));
}

TEST_F(InstallCli, WeaklyBalancedGridInstallsWithTheWeakRule) {
    const fs::path grid = fs::path(DUALHEX_SHARED_DATA) / "grids" / "sphere_weak_d5.leaves";
    if (!fs::exists(grid)) GTEST_SKIP() << grid << " not found";
    const Result r = run({"install", grid.string(), "-o", (dir_ / "weak").string(), "--json"});
    ASSERT_EQ(r.rc, 0) << r.err << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j["ok"].get<bool>());
    EXPECT_EQ(j["leaves"].get<std::size_t>(), 10816u);
}

TEST_F(InstallCli, WeaklyBalancedGridIsBadInputForTheStrongRule) {
    const fs::path grid = fs::path(DUALHEX_SHARED_DATA) / "grids" / "sphere_weak_d5.leaves";
    if (!fs::exists(grid)) GTEST_SKIP() << grid << " not found";
    const Result r = run({"install", grid.string(), "-o", (dir_ / "out").string(), "--json", "--balance", "strong"});
    EXPECT_EQ(r.rc, 3) << r.err;
    EXPECT_NE(r.err.find("not strongly balanced"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("(line "), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
}

// --certify writes the installed complex as a certificate that the independent checker
// (proofs/checker, no dualhex code) verifies; a tampered copy is rejected.
TEST_F(InstallCli, CertifiedInstallationIsVerifiedByTheIndependentChecker) {
    const fs::path grid = fs::path(DUALHEX_SHARED_DATA) / "grids" / "sphere_weak_d5.leaves";
    if (!fs::exists(grid)) GTEST_SKIP() << grid << " not found";
    const fs::path cert = dir_ / "install.cert";
    const Result r = run({"install", grid.string(), "-o", (dir_ / "c").string(), "--certify", cert.string()});
    ASSERT_EQ(r.rc, 0) << r.err;
    const Result ok = run({"--file", cert.string()}, DUALHEX_PROOF_CHECKER);
    EXPECT_EQ(ok.rc, 0) << ok.out << ok.err;
    EXPECT_NE(ok.out.find("VERIFIED"), std::string::npos) << ok.out;
    // tamper: drop the last vertex id of the first face loop (the first "f" line)
    std::string text = slurp(cert);
    const auto line = text.find("\nf ");
    ASSERT_NE(line, std::string::npos);
    const auto end = text.find('\n', line + 1);
    const auto last_space = text.rfind(' ', end);
    text.erase(last_space, end - last_space);
    const fs::path bad = dir_ / "tampered.cert";
    std::ofstream(bad) << text;
    const Result rejected = run({"--file", bad.string()}, DUALHEX_PROOF_CHECKER);
    EXPECT_NE(rejected.rc, 0) << rejected.out;
    EXPECT_EQ(rejected.out.find("VERIFIED"), std::string::npos) << rejected.out;
}

TEST_F(InstallCli, MalformedLeafFileIsInputError) {
    const fs::path grid = write("bad.leaves", "0 0 zero 0\n");
    const Result r = run({"install", grid.string(), "-o", (dir_ / "out").string()});
    EXPECT_EQ(r.rc, 3) << r.err;
}

}  // namespace

// A certificate of a level-16 grid would hold coordinates beyond the checker's 2^19 bound:
// refused before any work, exit 2, nothing written.
TEST_F(InstallCli, CertifyRefusesGridsBeyondTheCheckersBound) {
    std::string text;  // the corner cell split down to level 16 (a complete leaf set)
    for (int level = 1; level <= 16; ++level)
        for (int c = level == 16 ? 0 : 1; c < 8; ++c)
            text += std::to_string(level) + ' ' + std::to_string(c & 1) + ' ' + std::to_string((c >> 1) & 1) + ' ' +
                    std::to_string((c >> 2) & 1) + '\n';
    const fs::path grid = write("deep.leaves", text);
    const fs::path cert = dir_ / "deep.cert";
    const Result r = run({"install", grid.string(), "-o", (dir_ / "deep").string(), "--certify", cert.string()});
    EXPECT_EQ(r.rc, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("beyond the checker's bound"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(cert));
    EXPECT_FALSE(fs::exists(dir_ / "deep.poly.vtk"));
}


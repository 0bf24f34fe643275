// The CLI against hostile input and outputs (issue 15), run as a process: output paths are
// checked before any work (unwritable: exit 3 naming the path; existing without --force:
// exit 2, untouched), certify never overwrites into a non-empty directory without --force,
// JSON output survives file names that are not UTF-8, and bad surfaces or leaf files
// (self-intersecting, degenerate, too small, unparsable, FIFOs) are exit 3 with the file named.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_process.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

using Result = dualhex::test::ProcessResult;

const std::string kCubeOff =
    "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
    "3 0 2 1\n3 1 2 3\n3 4 5 6\n3 5 7 6\n3 0 1 4\n3 1 5 4\n3 2 6 3\n3 3 6 7\n3 0 4 2\n3 2 4 6\n3 1 3 5\n3 3 7 5\n";

class HostileCli : public dualhex::test::ScratchDirTest {
protected:
    HostileCli() : ScratchDirTest("dualhex_hostile_cli_") {}
    Result run(const std::vector<std::string>& args) const { return dualhex::test::run_process(DUALHEX_EXE, args, dir_); }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name, std::ios::binary) << text;
        return (dir_ / name).string();
    }
    std::string grid() const { return write("root.leaves", "1 0 0 0\n1 1 0 0\n1 0 1 0\n1 1 1 0\n1 0 0 1\n1 1 0 1\n1 0 1 1\n1 1 1 1\n"); }
};

void expect_rc(const Result& r, int rc, const std::string& in_stderr) {
    EXPECT_EQ(r.rc, rc) << r.err;
    EXPECT_NE(r.err.find(in_stderr), std::string::npos) << "stderr: " << r.err << "\nexpected: " << in_stderr;
}

TEST_F(HostileCli, UnwritableOutputsAreExit3BeforeAnyWork) {
    const std::string missing = (dir_ / "no" / "such" / "dir" / "out").string();
    // A bad input with a bad output: the output is reported, so it was checked first.
    const std::string bad_surface = write("bad.off", "OFF\n1 1 0\nnan 0 0\n");
    expect_rc(run({"mesh", bad_surface, "-o", missing + ".vtk"}), 3, missing + ".vtk: cannot write output");
    const std::string bad_grid = write("bad.leaves", "x\n");
    expect_rc(run({"grid", "balance", "--strong", bad_grid, "-o", missing}), 3, missing + ": cannot write output");
    expect_rc(run({"grid", "pair", bad_grid, "-o", missing}), 3, missing + ": cannot write output");
    expect_rc(run({"install", bad_grid, "-o", missing}), 3, missing + ".poly.vtk: cannot write output");
    expect_rc(run({"install", grid(), "-o", (dir_ / "ok").string(), "--certify", missing}), 3, missing + ": cannot write output");
    // An existing directory as the output file.
    fs::create_directory(dir_ / "d.vtk");
    expect_rc(run({"mesh", bad_surface, "-o", (dir_ / "d.vtk").string(), "--force"}), 3, "is a directory");
    // Certificates under a regular file, or a directory that cannot be created.
    const std::string file = write("plain", "x");
    expect_rc(run({"certify", "--out", file, "--force"}), 3, "plain: cannot write output");
    expect_rc(run({"certify", "--out", file + "/sub"}), 3, "cannot write output");
    expect_rc(run({"certify", "--out", "/proc/dualhex_certificates"}), 3, "cannot write output");
    expect_rc(run({"verify", "--only", "schemes", "--certify", file + "/sub"}), 3, "cannot write output");
}

TEST_F(HostileCli, NothingIsOverwrittenWithoutForce) {
    const std::string kept = write("out.vtk", "precious");
    expect_rc(run({"mesh", write("c.off", kCubeOff), "-o", kept}), 2, "exists; use --force");
    fs::create_directory(dir_ / "certs");
    const std::string mine = write("certs/elements.cert", "mine");
    expect_rc(run({"certify", "--out", (dir_ / "certs").string()}), 2, "is not empty; use --force");
    expect_rc(run({"verify", "--only", "schemes", "--certify", (dir_ / "certs").string()}), 2, "is not empty");
    std::ifstream in1(kept), in2(mine);
    std::string a, b;
    in1 >> a;
    in2 >> b;
    EXPECT_EQ(a, "precious");
    EXPECT_EQ(b, "mine");
}

TEST_F(HostileCli, JsonSurvivesNonUtf8FileNames) {
    const std::string name = (dir_ / "cu\xff\xfe" "be.off").string();
    std::ofstream(name) << kCubeOff;
    const std::string out = (dir_ / "o\xc3(.vtk").string();
    const Result r = run({"mesh", name, "-o", out, "--max-depth", "2", "--smooth", "0", "--json"});
    ASSERT_EQ(r.rc, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);  // throws (test error) if not valid JSON
    EXPECT_NE(j.at("input").get<std::string>().find("cu\\xff\\xfebe.off"), std::string::npos) << j.at("input");
    EXPECT_NE(j.at("output").get<std::string>().find("o\\xc3(.vtk"), std::string::npos) << j.at("output");
    EXPECT_TRUE(fs::exists(out));  // the file itself keeps its real name
    // Valid UTF-8 passes through unchanged.
    const std::string grid_name = (dir_ / "grille-\xc3\xa9t\xc3\xa9.leaves").string();
    fs::copy_file(grid(), grid_name);
    const Result g = run({"grid", "check", grid_name, "--json"});
    ASSERT_EQ(g.rc, 0) << g.err;
    EXPECT_EQ(nlohmann::json::parse(g.out).at("file"), grid_name);
}

TEST_F(HostileCli, BadSurfacesAreExit3NamingTheFile) {
    const std::string out = (dir_ / "o.vtk").string();
    std::string two_cubes = "OFF\n16 24 0\n";
    for (int c = 0; c < 2; ++c)
        for (int v = 0; v < 8; ++v)
            two_cubes += std::to_string((v & 1) + 0.5 * c) + ' ' + std::to_string((v >> 1 & 1) + 0.5 * c) + ' ' +
                         std::to_string((v >> 2 & 1) + 0.5 * c) + '\n';
    for (int c = 0; c < 2; ++c)
        for (std::size_t l = kCubeOff.find("3 0 2 1"); l < kCubeOff.size(); l = kCubeOff.find('\n', l) + 1) {
            std::istringstream face(kCubeOff.substr(l, kCubeOff.find('\n', l) - l));
            int n, a, b, d;
            face >> n >> a >> b >> d;
            two_cubes += "3 " + std::to_string(a + 8 * c) + ' ' + std::to_string(b + 8 * c) + ' ' + std::to_string(d + 8 * c) + '\n';
        }
    const std::string si = write("overlap.off", two_cubes);
    expect_rc(run({"mesh", si, "-o", out}), 3, si + ": surface is not embedded");
    std::string tiny = "OFF\n8 12 0\n";  // the cube scaled by 1e-200: valid, but beyond the floating-point stages
    for (int v = 0; v < 8; ++v)
        for (int d = 0; d < 3; ++d) tiny += std::string(v >> d & 1 ? "1e-200" : "0") + (d < 2 ? " " : "\n");
    const std::string small = write("tiny.off", tiny + kCubeOff.substr(kCubeOff.find("3 0 2 1")));
    expect_rc(run({"mesh", small, "-o", out}), 3, small + ": surface too small");
    const std::string flat = write("flat.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n");
    expect_rc(run({"mesh", flat, "-o", out}), 3, flat + ": surface is not embedded");
    const std::string nan = write("nan.obj", "v 0 0 0\nv nan 0 0\n");
    expect_rc(run({"mesh", nan, "-o", out}), 3, nan + ":2: not a finite decimal number (coordinate), 'nan'");
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(HostileCli, FifosAndDevicesAreRefusedNotRead) {
    const fs::path fifo = dir_ / "pipe.off";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    expect_rc(run({"mesh", fifo.string(), "-o", (dir_ / "o.vtk").string()}), 3, "not a regular file");
    expect_rc(run({"grid", "check", fifo.string()}), 3, "not a regular file");
    expect_rc(run({"grid", "check", "/dev/zero"}), 3, "/dev/zero: not a regular file");
    expect_rc(run({"install", "/dev/zero", "-o", (dir_ / "x").string()}), 3, "/dev/zero: not a regular file");
}

}  // namespace

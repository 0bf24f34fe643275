// `dualhex mesh --threads N` (issue 13): the written mesh (VTK and VTU bytes) and the --json
// report without its times are the same at 1, 2 and 4 threads, on the default torus, the
// bunny and a CAD block with sharp features (the features stage on). The comparison is
// shown to see a difference (one smoothing iteration less changes the bytes and the
// report), and --threads outside [1, 4096] is a usage error.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_process.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

using dualhex::test::ProcessResult;
using dualhex::test::slurp;

struct MeshRun {
    ProcessResult process;
    std::string mesh;     ///< the written file's bytes
    nlohmann::json report;  ///< --json without "ms" and "cpu_ms" (the times) and "output"
};

class MesherThreads : public dualhex::test::ScratchDirTest {
protected:
    MesherThreads() : ScratchDirTest("dualhex_mesher_threads_") {}

    // `dualhex mesh [input] -o OUT --threads N --json` plus `extra`; OUT named by the run.
    MeshRun mesh(const std::string& input, int threads, const std::string& ext, std::vector<std::string> extra = {}) {
        const std::string out = (dir_ / ("run" + std::to_string(runs_++) + ext)).string();
        std::vector<std::string> args{"mesh"};
        if (!input.empty()) args.push_back(input);
        for (const std::string& a : {std::string("-o"), out, std::string("--threads"), std::to_string(threads),
                                     std::string("--json")})
            args.push_back(a);
        args.insert(args.end(), extra.begin(), extra.end());
        MeshRun r{dualhex::test::run_process(DUALHEX_EXE, args, dir_), slurp(out), {}};
        if (r.process.rc == 0 || r.process.rc == 1) {  // 1: a failed check, the mesh and report still out
            r.report = nlohmann::json::parse(r.process.out);
            r.report.erase("ms");
            r.report.erase("cpu_ms");
            r.report.erase("output");  // the path, named by the run
        }
        return r;
    }

    // The model meshed at 1, 2 and 4 threads: the same exit code (0, or 1 for a mesh that
    // fails the check but is written and reported), same bytes, same report.
    void expect_same_at_every_thread_count(const std::string& input, const std::string& ext,
                                           const std::vector<std::string>& extra) {
        const MeshRun one = mesh(input, 1, ext, extra);
        ASSERT_TRUE(one.process.rc == 0 || one.process.rc == 1) << one.process.err;
        ASSERT_FALSE(one.mesh.empty());
        ASSERT_TRUE(one.report.contains("hexes"));
        for (const int threads : {2, 4}) {
            const MeshRun many = mesh(input, threads, ext, extra);
            ASSERT_EQ(many.process.rc, one.process.rc) << many.process.err;
            EXPECT_TRUE(many.mesh == one.mesh) << input << ": the " << ext << " bytes differ at " << threads << " threads";
            EXPECT_EQ(many.report, one.report) << input << ": the report differs at " << threads << " threads";
        }
    }

    int runs_ = 0;
};

std::string shared_surface(const std::string& name) { return std::string(DUALHEX_SHARED_DATA) + "/surfaces/" + name; }

}  // namespace

TEST_F(MesherThreads, TorusVtkAndVtuAreIdentical) {
    expect_same_at_every_thread_count("", ".vtk", {"--max-depth", "5"});
    expect_same_at_every_thread_count("", ".vtu", {"--max-depth", "5"});
}

TEST_F(MesherThreads, BunnyIsIdentical) {
    expect_same_at_every_thread_count(shared_surface("gao_bunny_tri.off"), ".vtk", {"--max-depth", "5"});
}

TEST_F(MesherThreads, BlockWithFeaturesIsIdentical) {
    // a CAD block: corners and feature curves snapped (the features stage's work)
    expect_same_at_every_thread_count(shared_surface("tue_block.stl"), ".vtk",
                                      {"--max-depth", "5", "--accept-topology-change"});
}

TEST_F(MesherThreads, TheComparisonSeesADifference) {
    const MeshRun five = mesh("", 2, ".vtk", {"--max-depth", "4"});
    const MeshRun four = mesh("", 2, ".vtk", {"--max-depth", "4", "--smooth", "4"});
    ASSERT_EQ(five.process.rc, 0) << five.process.err;
    ASSERT_EQ(four.process.rc, 0) << four.process.err;
    EXPECT_FALSE(four.mesh == five.mesh);
    EXPECT_NE(four.report, five.report);
}

TEST_F(MesherThreads, ThreadsOutOfRangeIsAUsageError) {
    for (const char* bad : {"0", "-1", "5000", "two"}) {
        const ProcessResult r = dualhex::test::run_process(
            DUALHEX_EXE, {"mesh", "-o", (dir_ / "x.vtk").string(), "--threads", bad}, dir_);
        EXPECT_EQ(r.rc, 2) << bad << ": " << r.err;
        EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir_ / "x.vtk"));
    }
}

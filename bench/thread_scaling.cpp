// thread_scaling: install (StrongRule) + clipped dual per phase for 1, 2, ... threads.
//
//   thread_scaling [--threads 1,2] [--reps N] [--grid FILE | --flat BASE] ...
//
// Per grid and thread count (a oneTBB task_arena of that size; more threads than cores are
// allowed), N repetitions of: grid checks (check_installable), leaf contexts, install (incl.
// its own grid checks and contexts), Incidence, clipped_dual. Prints the median, min and max
// wall seconds of each phase and the process CPU seconds of the install + dual, the speedup of
// the median against the first thread count, clipped-dual hexes per wall second, and checks
// that every run's complex and hexes equal the first run's (a digest of the complex with its
// edges, the dual points and hexes, printed to compare builds; bit-identical
// results are tested in tests/test_install_threads.cpp; here it guards the figures).
// A machine-readable line per (grid, threads): SCALING name threads leaves hexes
// checks contexts install incidence dual total cpu speedup Mhex_per_s.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/install.hpp"
#include "dualhex/install/leaf_contexts.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "flat_grid.hpp"
#include "install_dual_run.hpp"
#include "machine.hpp"
#include "thread_list.hpp"

using namespace dualhex;

namespace {

using bench::time_phase;

constexpr int kPhases = 7;  // checks, contexts, install, incidence, dual, total (install + dual), cpu
const char* const kNames[kPhases] = {"checks", "contexts", "install", "incidence", "dual", "total", "cpu"};

struct Sample {
    double t[kPhases] = {};
    std::size_t hexes = 0;
    std::uint64_t digest = 0;
};

std::uint64_t digest(const CellComplex& k, const ClippedDual& d) {
    std::uint64_t h = 1469598103934665603ULL;
    const auto mix = [&](std::uint64_t v) { h = (h ^ v) * 1099511628211ULL; };
    for (const auto& p : k.positions()) mix(static_cast<std::uint64_t>(p.x * 73856093 ^ p.y * 19349663 ^ p.z * 83492791));
    for (auto v : k.face_loops()) mix(static_cast<std::uint64_t>(v.idx));
    for (auto f : k.all_cell_halffaces()) mix(static_cast<std::uint64_t>(f.idx));
    for (std::size_t e = 0; e < k.n_edges(); ++e)
        for (VertexHandle v : k.edge_vertices(EdgeHandle(e))) mix(static_cast<std::uint64_t>(v.idx));
    for (std::size_t f = 0; f < k.n_faces(); ++f)
        for (EdgeHandle e : k.face_edges(FaceHandle(f))) mix(static_cast<std::uint64_t>(e.idx));
    for (const RationalPoint& p : d.points) {
        for (int a = 0; a < 3; ++a) mix(static_cast<std::uint64_t>(p.sum[a]));
        mix(static_cast<std::uint64_t>(p.denominator));
    }
    for (const auto& hex : d.hexes)
        for (auto i : hex) mix(i);
    return h;
}

Sample run_once(const LeafGrid& grid, const ElementLibrary& library) {
    Sample s;
    s.t[0] = time_phase([&] { (void)check_installable(grid); }).wall;
    s.t[1] = time_phase([&] { (void)leaf_contexts(grid); }).wall;
    const bench::InstallDualRun run = bench::run_install_dual(grid, StrongRule(), library);
    s.t[2] = run.install.wall;
    s.t[3] = run.incidence.wall;
    s.t[4] = run.clip.wall;
    s.t[5] = run.total().wall;
    s.t[6] = run.total().cpu;  // process CPU of install + dual (all threads)
    s.hexes = run.dual.hexes.size();
    s.digest = digest(run.installed.complex, run.dual);
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> threads = {1, 2};
    int reps = 5;
    std::vector<std::string> grids;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--threads" && a + 1 < argc) threads = bench::parse_thread_list(argv[++a]);
        else if (arg == "--reps" && a + 1 < argc) reps = std::max(1, std::atoi(argv[++a]));
        else if (arg == "--grid" && a + 1 < argc) grids.emplace_back(argv[++a]);
        else if (arg == "--flat" && a + 1 < argc) grids.emplace_back(std::string("flat:") + argv[++a]);
        else {
            std::fprintf(stderr, "usage: thread_scaling [--threads 1,2] [--reps N] [--grid FILE | --flat BASE] ...\n");
            return 2;
        }
    }
    const auto library = load_default_element_library();
    const int most = *std::max_element(threads.begin(), threads.end());
    const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(most));
    std::printf("cpu: %s; %d reps; wall seconds median [min, max]\n", bench::cpu_model().c_str(), reps);
    for (const std::string& g : grids) {
        const bool flat = g.rfind("flat:", 0) == 0;
        const LeafGrid grid = flat ? bench::flat_grid(std::atoi(g.c_str() + 5)) : read_leaf_file(g);
        const std::string name = flat ? g : std::filesystem::path(g).stem().string();
        double base_total = 0;
        std::uint64_t first_digest = 0;
        for (int th : threads) {
            std::vector<Sample> samples;
            tbb::task_arena arena(th);
            arena.execute([&] {
                for (int r = 0; r < reps; ++r) samples.push_back(run_once(grid, *library));
            });
            if (first_digest == 0) first_digest = samples.front().digest;
            bool same = true;
            for (const Sample& s : samples) same = same && s.digest == first_digest;
            double med[kPhases], lo[kPhases], hi[kPhases];
            for (int p = 0; p < kPhases; ++p) {
                std::vector<double> v;
                for (const Sample& s : samples) v.push_back(s.t[p]);
                std::sort(v.begin(), v.end());
                med[p] = v[v.size() / 2], lo[p] = v.front(), hi[p] = v.back();
            }
            if (base_total == 0) base_total = med[5];
            std::printf("%s, %zu leaves, %d thread(s)%s, digest %016llx\n", name.c_str(), grid.size(), th,
                        same ? "" : "  RESULT DIFFERS", static_cast<unsigned long long>(first_digest));
            for (int p = 0; p < kPhases; ++p)
                std::printf("  %-10s %8.4f [%.4f, %.4f]\n", kNames[p], med[p], lo[p], hi[p]);
            const double mhex = static_cast<double>(samples.front().hexes) / med[5] / 1e6;
            std::printf("  speedup %.2f, %.2f M hexes/s (install + dual, wall)\n", base_total / med[5], mhex);
            std::printf("SCALING %s %d %zu %zu %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.2f %.2f\n", name.c_str(), th, grid.size(),
                        samples.front().hexes, med[0], med[1], med[2], med[3], med[4], med[5], med[6], base_total / med[5], mhex);
        }
    }
    return 0;
}

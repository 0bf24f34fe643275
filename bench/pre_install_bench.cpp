// pre_install_bench: the stages before install, per phase, for 1, 2, ... oneTBB threads.
//
//   pre_install_bench [--threads 1,2] [--reps N] [--strong] [--preset coarse|medium|fine]
//                     [--grid FILE.leaves | --surface FILE] ...
//
// A surface: the octree (geometry::surface_octree with `dualhex mesh`'s options for the
// preset, default fine), then balance and pair as the mesher runs them (weak unless
// --strong), then the grid checks (is_paired, is_balanced). A leaf file: read once, then
// balance, pair and the checks (the shared sphere grids are already paired and balanced:
// there balance and pair are a full pass that splits nothing). Each phase's wall and
// process-CPU seconds (all threads), median of N runs, in a task arena of that many
// threads; every run's output grid is compared with the first one's (leaf by leaf) and a
// difference is reported, so the figures are of the same result.
// Under callgrind each phase is a part of its own (phase_mark.hpp; run_pre_install.sh
// CALLGRIND=1). A machine-readable line per (input, threads, phase):
// PHASE name threads phase wall_median cpu_median wall_min wall_max leaves_out
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/grid/refinement.hpp"
#include "dualhex/mesher/mesh_size.hpp"
#include "machine.hpp"
#include "thread_list.hpp"
#include "phase_mark.hpp"

using namespace dualhex;

namespace {

struct Input {
    std::string name;
    std::optional<geometry::AabbTree> tree;  // a surface
    std::optional<LeafGrid> grid;            // or a leaf file
};

struct Phase {
    const char* name;
    std::vector<bench::PhaseTime> runs;
    std::size_t leaves = 0;
};

// One run of every phase; `out` collects the final grid's leaves to compare runs.
void run_once(const Input& in, Balance mode, const geometry::SurfaceOctreeOptions& octree, std::vector<Phase>& phases,
              std::vector<Leaf>& out) {
    std::optional<LeafGrid> grid = in.grid;
    std::size_t p = 0;
    const auto timed = [&](const char* name, const std::function<void()>& f) {
        if (phases.size() <= p) phases.push_back({name, {}, 0});
        DUALHEX_PHASE_MARK("between phases");
        phases[p].runs.push_back(bench::time_phase(f));
        DUALHEX_PHASE_MARK(name);
        phases[p].leaves = grid ? grid->size() : 0;
        ++p;
    };
    if (in.tree) timed("octree", [&] { grid.emplace(geometry::surface_octree(*in.tree, octree).grid); });
    timed("balance", [&] { grid.emplace(balance(*grid, mode)); });
    timed("pair", [&] { grid.emplace(pair(*grid, mode)); });
    timed("checks", [&] {
        if (!is_paired(*grid).ok || !is_balanced(*grid, mode).ok) std::fprintf(stderr, "CHECK FAILED\n");
    });
    out = grid->leaves();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

void report(const Input& in, int threads, const std::vector<Phase>& phases) {
    double wall = 0, cpu = 0;
    for (const Phase& ph : phases) {
        std::vector<double> w, c;
        for (const auto& t : ph.runs) w.push_back(t.wall), c.push_back(t.cpu);
        const auto [lo, hi] = std::minmax_element(w.begin(), w.end());
        std::printf("PHASE %s %d %s %.4f %.4f %.4f %.4f %zu\n", in.name.c_str(), threads, ph.name, median(w), median(c),
                    *lo, *hi, ph.leaves);
        wall += median(w), cpu += median(c);
    }
    std::printf("PHASE %s %d total %.4f %.4f 0 0 0\n", in.name.c_str(), threads, wall, cpu);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> threads = {1, 2};
    int reps = 3;
    Balance mode = Balance::Weak;
    mesher::MeshPreset preset = mesher::MeshPreset::Fine;
    std::vector<Input> inputs;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--threads" && a + 1 < argc) threads = bench::parse_thread_list(argv[++a]);
        else if (arg == "--reps" && a + 1 < argc) reps = std::max(1, std::atoi(argv[++a]));
        else if (arg == "--strong") mode = Balance::Strong;
        else if (arg == "--preset" && a + 1 < argc && mesher::parse_mesh_preset(argv[a + 1])) preset = *mesher::parse_mesh_preset(argv[++a]);
        else if (arg == "--grid" && a + 1 < argc) {
            const std::string g = argv[++a];
            inputs.push_back({std::filesystem::path(g).stem().string(), std::nullopt, read_leaf_file(g)});
        } else if (arg == "--surface" && a + 1 < argc) {
            const std::string s = argv[++a];
            inputs.push_back({std::filesystem::path(s).stem().string(), geometry::AabbTree(geometry::read_surface(s)), std::nullopt});
        } else {
            std::fprintf(stderr, "usage: pre_install_bench [--threads 1,2] [--reps N] [--strong] [--preset P] "
                                 "[--grid FILE | --surface FILE] ...\n");
            return 2;
        }
    }
    const int most = *std::max_element(threads.begin(), threads.end());
    const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(most));
    std::printf("cpu: %s; %d reps; %s balance; seconds, median\n", bench::cpu_model().c_str(), reps,
                mode == Balance::Weak ? "weak" : "strong");
    for (const Input& in : inputs) {
        const geometry::SurfaceOctreeOptions octree =
            in.tree ? mesher::octree_options(mesher::mesh_preset(preset), in.tree->bounds()) : geometry::SurfaceOctreeOptions{};
        std::vector<Leaf> first;
        for (int th : threads) {
            std::vector<Phase> phases;
            bool same = true;
            tbb::task_arena arena(th);
            arena.execute([&] {
                for (int r = 0; r < reps; ++r) {
                    std::vector<Leaf> out;
                    run_once(in, mode, octree, phases, out);
                    if (first.empty()) first = out;
                    same = same && out == first;
                }
            });
            std::printf("%s, %d thread(s), %zu leaves out%s\n", in.name.c_str(), th, first.size(),
                        same ? "" : "  RESULT DIFFERS");
            report(in, th, phases);
        }
    }
    return 0;
}

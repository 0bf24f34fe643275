// mesh_bench: the `dualhex mesh` pipeline (mesher/mesh_pipeline.hpp) on every surface
// model of the shared data set at max depth 6 (weak balance, default smoothing).
//
//   mesh_bench [--depth N] [--strong] [model ...]   (default: every file in surfaces/)
//
// Per model: milliseconds per stage, leaves, hexes, scaled Jacobian (min, mean), share
// inverted (SJ < 0) and < 0.2, one-sided surface distance. Prints the machine first.
// Writing is not timed here (the CLI times it).
#include "machine.hpp"
#include <sys/utsname.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/geometry/surface.hpp"

using namespace dualhex;
using namespace dualhex::geometry;
using namespace dualhex::mesher;

int main(int argc, char** argv) {
    int depth = 6;
    Balance balance = Balance::Weak;
    std::vector<std::string> models;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--depth" && a + 1 < argc) depth = std::stoi(argv[++a]);
        else if (arg == "--strong") balance = Balance::Strong;
        else models.push_back(arg);
    }
    if (models.empty()) {
        for (const auto& e : std::filesystem::directory_iterator(std::string(DUALHEX_SHARED_DATA) + "/surfaces"))
            models.push_back(e.path().string());
        std::sort(models.begin(), models.end());
    }

    utsname u{};
    uname(&u);
    std::printf("machine: %s, CPU: %s\n", u.nodename, dualhex::bench::cpu_model().c_str());
    std::printf("max depth %d, %s balance; times in ms\n\n", depth, balance == Balance::Weak ? "weak" : "strong");
    std::printf("%-18s %7s %7s %7s %7s %7s %6s %7s %7s %6s %6s %7s | %7s %7s %8s %7s %7s %7s %8s\n", "model", "leaves",
                "hexes", "octree", "pair", "install", "verify", "dual", "core", "pad", "opt", "total", "SJ_min",
                "SJ_mean", "inverted", "<0.2", "inv_pad", "haus", "sing");
    int failures = 0;
    for (const auto& path : models) {
        const std::string name = std::filesystem::path(path).filename().string();
        try {
            const auto t0 = std::chrono::steady_clock::now();
            const AabbTree tree(read_surface(path));
            MeshPipelineOptions options;
            options.max_depth = depth;
            options.balance = balance;
            const MeshPipelineResult r = mesh_surface(tree, options);
            const double total = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            std::size_t singular = 0;
            for (const auto& [v, n] : r.singular_edge_valences) singular += n;
            const auto& m = r.ms;
            std::printf("%-18s %7zu %7zu %7.0f %7.0f %7.0f %6.0f %7.0f %7.0f %6.0f %6.0f %7.0f | %7.3f %7.3f %7.3f%% %6.2f%% "
                        "%7zu %7.4f %8zu\n",
                        name.c_str(), r.leaves, r.mesh.hexes.size(), m.octree, m.balance_pair, m.install, m.verify, m.dual,
                        m.core, m.pad, m.smooth + m.optimise, total, r.quality.min, r.quality.mean,
                        100 * r.quality.share_negative, 100 * r.quality.share_below_02, r.inverted_after_pad,
                        r.hausdorff.max, singular);
            std::fflush(stdout);
        } catch (const std::exception& e) {
            std::printf("%-18s FAILED: %s\n", name.c_str(), e.what());
            ++failures;
        }
    }
    std::printf("\ncolumns: core = core selection + repair, pad = pad layer, opt = smoothing + optimiser, total "
                "includes reading the file and the AABB tree, the check and the report; inverted = share of hexes with "
                "SJ < 0, <0.2 = share with SJ < 0.2, inv_pad = hexes inverted right after padding (before "
                "smoothing/optimising), haus = max sampled "
                "boundary-to-surface distance / bbox diagonal, sing = interior singular edges\n");
    return failures == 0 ? 0 : 1;
}

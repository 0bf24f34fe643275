// mesh_stage_bench: one `dualhex mesh` case (mesher/mesh_pipeline.hpp) timed per stage, in
// its own process so the peak memory is the case's own. bench/run_mesh.sh runs the table.
//
//   mesh_stage_bench MODEL [--depth N] [--strong] [--out FILE]   (default depth 6, weak)
//
// Prints one line: TABLE model depth balance leaves dual_hexes hexes read octree balance pair
// install verify dual extract proj_smooth write total hexes_per_s peak_MB
// (times in ms, wall clock; read = surface + AABB tree; extract = the core stage;
// proj_smooth = pad + smoothing + optimiser + check + report; write = the hex mesh as FILE, default a temporary .vtk
// that is removed; hexes_per_s = clipped-dual hexes / (install + dual); peak = max RSS).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/geometry/surface.hpp"
#include "machine.hpp"

using namespace dualhex;
using namespace dualhex::geometry;
using namespace dualhex::mesher;

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

using bench::peak_rss_mb;

}  // namespace

int main(int argc, char** argv) {
    std::string model, out;
    MeshPipelineOptions options;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--depth" && a + 1 < argc) options.max_depth = std::stoi(argv[++a]);
        else if (arg == "--strong") options.balance = Balance::Strong;
        else if (arg == "--out" && a + 1 < argc) out = argv[++a];
        else model = arg;
    }
    if (model.empty()) {
        std::fprintf(stderr, "usage: mesh_stage_bench MODEL [--depth N] [--strong] [--out FILE]\n");
        return 2;
    }
    const bool temporary = out.empty();
    if (temporary)
        out = (std::filesystem::temp_directory_path() / ("mesh_stage_bench_" + std::to_string(::getpid()) + ".vtk"))
                  .string();
    try {
        const auto start = Clock::now();
        const AabbTree tree(read_surface(model));
        const double read = ms_since(start);
        MeshPipelineResult r = mesh_surface(tree, options);
        auto t0 = Clock::now();
        write_hex_mesh(out, r.mesh, true);
        r.ms.write = ms_since(t0);
        if (temporary) std::filesystem::remove(out);
        const double total = ms_since(start);
        const auto& m = r.ms;
        const double proj_smooth = m.pad + m.smooth + m.optimise + m.check + m.report;
        std::printf("TABLE %s %d %s %zu %zu %zu %.0f %.0f %.0f %.0f %.0f %.0f %.0f %.0f %.0f %.0f %.0f %.0f %.0f\n",
                    std::filesystem::path(model).stem().c_str(), options.max_depth,
                    options.balance == Balance::Weak ? "weak" : "strong", r.leaves, r.dual_hexes, r.mesh.hexes.size(),
                    read, m.octree, m.balance, m.pair, m.install, m.verify, m.dual, m.core, proj_smooth, m.write,
                    total, 1000.0 * static_cast<double>(r.dual_hexes) / (m.install + m.dual), peak_rss_mb());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mesh_stage_bench: %s: %s\n", model.c_str(), e.what());
        return 1;
    }
    return 0;
}

// install_bench: times element installation (install/install.hpp) and the checks after it.
//
//   install_bench [--elements DIR] [--grid FILE ...] [--flat BASE ...] [--verify] [base levels ...]
//                                                  (default: flat 4 5, then the sphere grids)
// --flat BASE puts the generated flat grid of levels BASE/BASE+1 (9 * 8^BASE / 2 leaves:
// 1.18M for 6, 9.4M for 7) through the strong-rule table instead of a leaf file.
//
// Flat grids: root refined to level `base`, the half y < 1/2 to base + 1 (paired, strongly
// balanced, flat transitions only), installed with FlatOnlyRule (outside-root cubes
// mirrored, so the side walls stay flat). Then the shared strongly balanced sphere grids
// (or the --grid files) with the StrongRule: install, Incidence + clipped dual, per leaf.
// Times are wall seconds and process CPU seconds; memory is the peak resident set size
// (the process's peak at the end of each phase: the phase that raised it is the first row
// showing the final figure; the rows are printed after all phases ran).
// A machine-readable line per grid: TABLE name leaves cells hexes install_cpu dual_cpu
// sum_cpu us_per_leaf peak_MB (bench/run_install.sh runs one grid per process).
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "dualhex/install.hpp"
#include "flat_grid.hpp"
#include "install_dual_run.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/validation.hpp"

using namespace dualhex;

namespace {

using bench::cpu_seconds;
using bench::peak_rss_mb;

double now() { return bench::wall_seconds(); }

std::string fmt(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", x);
    return b;
}

using bench::flat_grid;

long minor_faults() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_minflt;
}

// peak_mb < 0: the peak so far (a phase timed just now); else the peak at the phase's end.
void row(const char* what, double seconds, const std::string& extra = {}, double peak_mb = -1) {
    static long faults = 0;
    const long now_faults = minor_faults();
    std::printf("  %-28s %8.3f s  peak %7.1f MB  faults %7ld  %s\n", what, seconds, peak_mb < 0 ? peak_rss_mb() : peak_mb,
                now_faults - faults, extra.c_str());
    faults = now_faults;
}

}  // namespace

int main(int argc, char** argv) {
    std::filesystem::path elements;
    std::vector<int> bases;
    std::vector<std::filesystem::path> grids;
    std::vector<int> strong_flat;  // --flat BASE: generated flat grid through the strong-rule table
    bool verify = false;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--elements" && a + 1 < argc) {
            elements = argv[++a];
        } else if (arg == "--grid" && a + 1 < argc) {
            grids.emplace_back(argv[++a]);
        } else if (arg == "--flat" && a + 1 < argc) {
            strong_flat.push_back(std::atoi(argv[++a]));
        } else if (arg == "--verify") {
            verify = true;
        } else {
            bases.push_back(std::atoi(arg.c_str()));
        }
    }
    if (bases.empty() && grids.empty() && strong_flat.empty()) bases = {4, 5};
    std::shared_ptr<const ElementLibrary> library;
    try {
        library = elements.empty() ? load_default_element_library() : load_element_library(elements);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "install_bench: cannot load the element library: %s\n", e.what());
        return 3;
    }
    const FlatOnlyRule rule;

    for (int base : bases) {
        double t = now();
        const LeafGrid grid = flat_grid(base);
        std::printf("flat grid, levels %d/%d: %zu leaves\n", base, base + 1, grid.size());
        row("grid (LeafGrid)", now() - t);
        t = now();
        const InstallCheck ok = check_installable(grid);
        row("paired + strongly balanced", now() - t, ok.ok ? "ok" : ok.message);
        t = now();
        const std::vector<LeafContext> contexts = leaf_contexts(grid, OutsideRoot::Mirror);
        row("leaf contexts", now() - t);
        t = now();
        InstallResult r;
        try {
            r = install(grid, rule, *library, {.outside_root = OutsideRoot::Mirror});
        } catch (const std::exception& e) {
            std::printf("  install failed: %s\n", e.what());
            continue;
        }
        const double t_install = now() - t;
        std::string used;
        for (const auto& [name, n] : r.elements_used()) used += name + ":" + std::to_string(n) + " ";
        row("install (incl. grid checks)", t_install,
            std::to_string(r.complex.n_cells()) + " cells, " + std::to_string(r.complex.n_faces()) + " faces, " +
                std::to_string(r.complex.n_vertices()) + " vertices; " + used);
        t = now();
        const DualResult dual = interior_dual(r.complex);
        const double t_dual = now() - t;
        row("interior_dual", t_dual, std::to_string(dual.mesh.hexes.size()) + " hexes, " +
                                         std::to_string(dual.errors.size()) + " non-cubes");
        row("install + dual", t_install + t_dual);
        t = now();
        const InstallVerification v = verify_installation(r);
        row("verify_installation", now() - t, v.summary());
    }

    // Strong rule on real grids: the sphere grids (or files given with --grid), one row of
    // phases each: install (incl. grid checks), Incidence + clipped dual, and the per-leaf
    // cost. Wall and CPU seconds (the machine's cores are shared).
    std::vector<std::filesystem::path> files = grids;
    for (int base : strong_flat) files.emplace_back("flat:" + std::to_string(base));
    if (files.empty() && strong_flat.empty())
        for (int d : {5, 6, 7})
            files.push_back(std::filesystem::path(DUALHEX_SHARED_DATA) / "grids" / ("sphere_strong_d" + std::to_string(d) + ".leaves"));
    const StrongRule strong;
    for (const auto& file : files) {
        const std::string name = file.string();
        const bool generated = name.rfind("flat:", 0) == 0;
        if (!generated && !std::filesystem::exists(file)) continue;
        double t = now(), c = cpu_seconds();
        const LeafGrid grid = generated ? flat_grid(std::atoi(name.c_str() + 5)) : read_leaf_file(file);
        std::printf("%s: %zu leaves (strong rule)\n", file.filename().c_str(), grid.size());
        row("read", now() - t, "cpu " + fmt(cpu_seconds() - c));
        if (std::getenv("INSTALL_BENCH_PHASES")) {
            c = cpu_seconds();
            const InstallCheck ok = check_installable(grid);
            row("  phase: grid checks", cpu_seconds() - c, ok.ok ? "ok (cpu)" : ok.message);
            c = cpu_seconds();
            const std::vector<LeafContext> contexts = leaf_contexts(grid, OutsideRoot::Coarse);
            row("  phase: leaf contexts", cpu_seconds() - c, "(cpu)");
        }
        bench::InstallDualRun run;
        try {
            run = bench::run_install_dual(grid, strong, *library);
        } catch (const std::exception& e) {
            std::printf("  install refused: %.160s\n", e.what());
            continue;
        }
        const InstallResult& r = run.installed;
        const bench::PhaseTime dual{run.incidence.wall + run.clip.wall, run.incidence.cpu + run.clip.cpu};
        const bench::PhaseTime total = run.total();
        row("install (incl. grid checks)", run.install.wall,
            "cpu " + fmt(run.install.cpu) + "; " + std::to_string(r.complex.n_cells()) + " cells, " +
                std::to_string(r.complex.n_vertices()) + " vertices",
            run.install.peak_mb);
        row("Incidence", run.incidence.wall, "cpu " + fmt(run.incidence.cpu), run.incidence.peak_mb);
        row("clipped_dual", run.clip.wall,
            "cpu " + fmt(run.clip.cpu) + "; " + std::to_string(run.dual.hexes.size()) + " hexes, " +
                std::to_string(run.dual.errors.size()) + " non-cubes",
            run.clip.peak_mb);
        const double us_per_leaf = 1e6 * total.cpu / static_cast<double>(grid.size());
        row("install + dual", total.wall, "cpu " + fmt(total.cpu) + "; " + fmt(us_per_leaf) + " us/leaf (cpu)");
        std::printf("TABLE %s %zu %zu %zu %.3f %.3f %.3f %.3f %.1f\n", file.filename().c_str(), grid.size(),
                    r.complex.n_cells(), run.dual.hexes.size(), run.install.cpu, dual.cpu, total.cpu, us_per_leaf,
                    peak_rss_mb());
        if (verify) {
            t = now();
            const InstallVerification v = verify_installation(r);
            row("verify_installation", now() - t, v.summary());
        }
    }
    return 0;
}

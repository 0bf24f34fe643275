// install_bench: times element installation (checkers/install.hpp) and the checks after it.
//
//   install_bench [--elements DIR] [base levels ...]      (default: 4 5)
//
// Flat grids: root refined to level `base`, the half y < 1/2 to base + 1 (paired, strongly
// balanced, flat transitions only), installed with FlatOnlyRule (outside-root cubes
// mirrored, so the side walls stay flat). Then the shared sphere grids: they need the full
// rule, so only the grid checks and the leaf contexts are timed and the flat-only rule's
// refusal is shown. Times are wall seconds; memory is the peak resident set size.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "dualhex/checkers/install.hpp"
#include "dualhex/checkers/library.hpp"
#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/validation.hpp"

using namespace dualhex;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double peak_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;
}

LeafGrid flat_grid(int base) {
    std::vector<Leaf> leaves;
    const std::int64_t n = std::int64_t{1} << base;
    for (std::int64_t i = 0; i < n; ++i)
        for (std::int64_t j = 0; j < n; ++j)
            for (std::int64_t k = 0; k < n; ++k) {
                const Leaf c{base, i, j, k};
                if (2 * j < n) {
                    for (const Leaf& ch : children(c)) leaves.push_back(ch);
                } else {
                    leaves.push_back(c);
                }
            }
    return LeafGrid(std::move(leaves));
}

void row(const char* what, double seconds, const std::string& extra = {}) {
    std::printf("  %-28s %8.3f s  peak %7.1f MB  %s\n", what, seconds, peak_mb(), extra.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    std::filesystem::path elements;
    std::vector<int> bases;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--elements" && a + 1 < argc) {
            elements = argv[++a];
        } else {
            bases.push_back(std::atoi(arg.c_str()));
        }
    }
    if (bases.empty()) bases = {4, 5};
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

    for (int d : {5, 6, 7}) {
        const std::filesystem::path file =
            std::filesystem::path(DUALHEX_SHARED_DATA) / "grids" / ("sphere_strong_d" + std::to_string(d) + ".leaves");
        if (!std::filesystem::exists(file)) continue;
        double t = now();
        const LeafGrid grid = read_leaf_file(file);
        std::printf("%s: %zu leaves\n", file.filename().c_str(), grid.size());
        row("read", now() - t);
        t = now();
        const InstallCheck ok = check_installable(grid);
        row("paired + strongly balanced", now() - t, ok.ok ? "ok" : ok.message);
        t = now();
        const std::vector<LeafContext> contexts = leaf_contexts(grid, OutsideRoot::Coarse);
        const double t_ctx = now() - t;
        std::map<std::string, std::size_t> patterns;
        for (const LeafContext& c : contexts) ++patterns[c.local_pattern_name()];
        row("leaf contexts", t_ctx, std::to_string(patterns.size()) + " distinct local patterns around P");
        try {
            (void)install(grid, rule, *library);
            std::printf("  install: unexpectedly accepted by the flat-only rule\n");
        } catch (const std::exception& e) {
            std::printf("  install (flat-only rule): refused: %.160s\n", e.what());
        }
    }
    return 0;
}

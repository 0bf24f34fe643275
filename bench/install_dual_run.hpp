#pragma once
// One timed run of what both install benchmarks measure: install(grid, rule) followed by the
// Incidence and the clipped dual over the root cube. Inputs: a paired, balanced grid, the
// rule and its element library. Output: the installation, its clipped dual and the three
// phases' wall and CPU seconds. install() throws (std::exception) on a grid it refuses.
#include <optional>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
// Under callgrind, each phase's instructions are dumped as a part of their own (named by
// the phase; bench/run_threads.sh CALLGRIND=1 reads them); elsewhere a no-op.
#define DUALHEX_PHASE_MARK(name) CALLGRIND_DUMP_STATS_AT(name)
#else
#define DUALHEX_PHASE_MARK(name) ((void)0)
#endif

#include "dualhex/install.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "machine.hpp"

namespace dualhex::bench {

struct InstallDualRun {
    InstallResult installed;
    ClippedDual dual;
    PhaseTime install, incidence, clip;  // clip = clipped_dual given the Incidence

    [[nodiscard]] PhaseTime total() const {
        return {install.wall + incidence.wall + clip.wall, install.cpu + incidence.cpu + clip.cpu};
    }
};

inline InstallDualRun run_install_dual(const LeafGrid& grid, const TransitionRule& rule, const ElementLibrary& library) {
    InstallDualRun run;
    DUALHEX_PHASE_MARK("before install");
    run.install = time_phase([&] { run.installed = install(grid, rule, library); });
    DUALHEX_PHASE_MARK("install");
    const InstallResult& r = run.installed;
    std::optional<Incidence> incidence;
    run.incidence = time_phase([&] { incidence.emplace(r.complex); });
    DUALHEX_PHASE_MARK("incidence");
    const std::int64_t extent = r.unit << r.max_level;
    run.clip = time_phase([&] { run.dual = clipped_dual(r.complex, *incidence, {0, 0, 0}, {extent, extent, extent}); });
    DUALHEX_PHASE_MARK("clipped dual");
    return run;
}

}  // namespace dualhex::bench

#pragma once
// One timed run of what both install benchmarks measure: install(grid, rule) followed by the
// Incidence and the clipped dual over the root cube. Inputs: a paired, balanced grid, the
// rule and its element library. Output: the installation, its clipped dual and the three
// phases' wall and CPU seconds. install() throws (std::exception) on a grid it refuses.
#include <optional>

#include "dualhex/install.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "machine.hpp"
#include "phase_mark.hpp"  // each phase its own callgrind part

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

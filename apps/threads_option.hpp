#pragma once
// `--threads N` of the heavy commands (verify, install, mesh): oneTBB's worker limit while the
// command runs; default (0) = every core. Results never depend on it: every parallel loop
// writes each item's output to its own slot and merges in a fixed order.
#include <optional>

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

namespace dualhex::app {

inline CLI::Option* add_threads_option(CLI::App& sub, int& threads) {
    return sub
        .add_option("--threads", threads, "Worker threads (default: all cores; the results do not depend on it)")
        ->check(CLI::Range(1, 4096));
}

/// Caps oneTBB's parallelism at `threads` while alive (0: no cap).
class ThreadLimit {
public:
    explicit ThreadLimit(int threads) {
        if (threads > 0) control_.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    }

private:
    std::optional<tbb::global_control> control_;
};

}  // namespace dualhex::app

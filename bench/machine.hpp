#pragma once
// The machine a benchmark ran on and the clocks it reads (figures are only meaningful with
// the machine named, and wall time alone lies on a shared machine: CPU time goes beside it).
#include <sys/resource.h>

#include <time.h>

#include <chrono>
#include <fstream>
#include <string>

namespace dualhex::bench {

/// The CPU model from /proc/cpuinfo ("unknown" elsewhere).
inline std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown";
}

/// Monotonic wall-clock seconds (an arbitrary origin: subtract two readings).
inline double wall_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// CPU seconds of the whole process, every thread summed.
inline double cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The process's peak resident set size so far, in MB.
inline double peak_rss_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;
}

/// Wall and CPU seconds of one timed phase, and the process's peak RSS (MB) at its end.
struct PhaseTime {
    double wall = 0, cpu = 0, peak_mb = 0;
};

/// Runs f() and returns its wall and process-CPU seconds (and the peak RSS so far).
template <class F>
PhaseTime time_phase(F&& f) {
    const double w = wall_seconds(), c = cpu_seconds();
    f();
    return {wall_seconds() - w, cpu_seconds() - c, peak_rss_mb()};
}

}  // namespace dualhex::bench

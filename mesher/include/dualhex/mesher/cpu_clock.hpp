#pragma once
// CPU time in milliseconds, for the stage times (measuring only, never for results): the
// whole process's (every thread's) and the calling thread's.
#include <ctime>

namespace dualhex::mesher {

inline double cpu_clock_ms(clockid_t clock) {
    timespec t{};
    clock_gettime(clock, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}
inline double process_cpu_ms() { return cpu_clock_ms(CLOCK_PROCESS_CPUTIME_ID); }
inline double thread_cpu_ms() { return cpu_clock_ms(CLOCK_THREAD_CPUTIME_ID); }

}  // namespace dualhex::mesher

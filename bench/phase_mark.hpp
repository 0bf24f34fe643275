#pragma once
// DUALHEX_PHASE_MARK(name): under callgrind, the instructions since the last mark are dumped
// as a part of their own named `name` (bench/run_threads.sh and run_pre_install.sh with
// CALLGRIND=1 read them); elsewhere a no-op.
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define DUALHEX_PHASE_MARK(name) CALLGRIND_DUMP_STATS_AT(name)
#else
#define DUALHEX_PHASE_MARK(name) ((void)0)
#endif

#!/bin/sh
# The stages before install (surface octree, balance, pair, grid checks) per phase, wall and
# process CPU, for 1 and 2 threads (THREADS=1,2,4), REPS runs each (default 3):
# bench/pre_install_bench on sphere_strong_d7 (strong) and the bunny at the fine preset
# (weak, as `dualhex mesh --preset fine`), or the inputs given (pre_install_bench's options).
# With CALLGRIND=1 it also counts instructions per phase for each thread count (valgrind
# --tool=callgrind, one run each): the main thread's share (about the wall time on free
# cores; under valgrind threads run one at a time, so it includes its spinning while it
# waits) and all threads' total; the noise-free measure on a loaded machine.
# Not part of the test suite.
#   bench/run_pre_install.sh [--strong] [--grid FILE.leaves | --surface FILE ...]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
bench_build pre_install_bench
bench_header
b="$build/bench/pre_install_bench"
opts="--reps ${REPS:-3} --threads ${THREADS:-1,2}"
run() {  # ARGS...: the table, then the instruction counts if asked
  # shellcheck disable=SC2086
  "$b" $opts "$@"
  [ "${CALLGRIND:-0}" = 1 ] || return 0
  for t in $(echo "${THREADS:-1,2}" | tr ',' ' '); do
    d=$(mktemp -d)
    valgrind --tool=callgrind --separate-threads=yes --callgrind-out-file="$d/main" "$b" --reps 1 --threads "$t" "$@" >/dev/null 2>&1
    valgrind --tool=callgrind --separate-threads=no --callgrind-out-file="$d/all" "$b" --reps 1 --threads "$t" "$@" >/dev/null 2>&1
    for phase in octree balance pair checks; do
      ir() { for f in "$d"/$1*; do
        if grep -q "^desc: Trigger: Client Request: $phase\$" "$f" && { [ "$1" = all ] || grep -q '^thread: 1$' "$f"; }; then
          awk '/^(summary|totals):/ { print $2; exit }' "$f"; fi; done; }
      m=$(ir main); [ -n "$m" ] || continue
      printf 'INSTR %s threads %-8s main %15s all %15s\n' "$t" "$phase" "$m" "$(ir all)"
    done
    rm -rf "$d"
  done
}
if [ $# -gt 0 ]; then
  run "$@"
else
  run --strong --grid "$data/grids/sphere_strong_d7.leaves"
  run --preset fine --surface "$data/surfaces/gao_bunny_tri.off"
fi

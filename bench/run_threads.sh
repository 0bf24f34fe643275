#!/bin/sh
# Thread scaling of install (StrongRule) + clipped dual: bench/thread_scaling on the shared
# strongly balanced sphere grids (or the grids given: FILE.leaves or flat:BASE), 1 and 2
# threads (THREADS, e.g. THREADS=1,2,4), REPS repetitions each (default 5), one process per
# grid. Prints per-phase wall seconds (median [min, max]: the spread says how noisy the
# machine was) and a summary table. With CALLGRIND=1 it also counts instructions per phase
# (valgrind --tool=callgrind: the main thread's share, about the wall time on free cores,
# and all threads' sum, the extra work parallel runs do): the noise-free measure on a
# loaded machine. Not part of the test suite.
#   bench/run_threads.sh [GRID.leaves | flat:BASE ...]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
reps="${REPS:-5}"
threads="${THREADS:-1,2}"
bench_build thread_scaling
if [ $# -eq 0 ]; then set -- "$data/grids/sphere_strong_d5.leaves" "$data/grids/sphere_strong_d6.leaves" "$data/grids/sphere_strong_d7.leaves"; fi
bench_header
out=$(mktemp)
for g in "$@"; do
  case "$g" in flat:*) args="--flat ${g#flat:}" ;; *) args="--grid $g" ;; esac
  # shellcheck disable=SC2086
  "$build/bench/thread_scaling" --reps "$reps" --threads "$threads" $args | tee -a "$out" | grep -v '^SCALING'
done
echo
echo "wall seconds (median of $reps); total = install + Incidence + clipped dual; cpu = process CPU of the total"
printf '%-18s %3s %9s %9s %7s %7s %7s %7s %7s %7s %7s %7s %6s\n' grid thr leaves hexes checks context install incid dual total cpu speedup Mhex/s
awk '/^SCALING/ { printf "%-18s %3d %9d %9d %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f %7.2f %6.2f\n", $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14 }' "$out"
rm -f "$out"
if [ "${CALLGRIND:-0}" = 1 ]; then
  # Per phase (install_dual_run.hpp dumps at each phase's end): the main thread's share
  # (--separate-threads; under valgrind threads run one at a time, so it includes the main
  # thread's spinning while it waits) and all threads' total (a second run).
  echo
  echo "instructions per phase (callgrind, one run each): main thread / all threads"
  for g in "$@"; do
    case "$g" in flat:*) args="--flat ${g#flat:}" ;; *) args="--grid $g" ;; esac
    for t in $(echo "$threads" | tr ',' ' '); do
      d=$(mktemp -d)
      for mode in main all; do
        sep=no; [ "$mode" = main ] && sep=yes
        # shellcheck disable=SC2086
        valgrind --tool=callgrind --separate-threads=$sep --callgrind-out-file="$d/$mode" "$build/bench/thread_scaling" --reps 1 --threads "$t" $args >/dev/null 2>&1
      done
      for phase in install incidence "clipped dual"; do
        ir() { for f in "$d"/$1*; do
          if grep -q "^desc: Trigger: Client Request: $phase\$" "$f" && { [ "$1" = all ] || grep -q '^thread: 1$' "$f"; }; then
            awk '/^(summary|totals):/ { print $2; exit }' "$f"; fi; done; }
        printf '%-30s %2d threads %-13s %15s / %15s Ir\n' "$(basename "$g")" "$t" "$phase" "$(ir main)" "$(ir all)"
      done
      rm -rf "$d"
    done
  done
fi

#!/bin/sh
# Times install (StrongRule) + clipped dual on the shared strongly balanced sphere grids (or
# the leaf files given), one process per grid so each peak memory is its own, and prints a
# table. Builds install_bench in the root build (Release, build/ unless BUILD_DIR is set).
#   bench/run_install.sh [GRID.leaves | flat:BASE ...]
# flat:BASE is the generated flat grid of levels BASE/BASE+1 (flat:6 1.18M leaves, flat:7 9.4M
# leaves, ~7 GB peak).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build="${BUILD_DIR:-$here/../build}"
cmake -S "$here/.." -B "$build" -DCMAKE_BUILD_TYPE=Release -DDUALHEX_BUILD_BENCH=ON >/dev/null
cmake --build "$build" -j2 --target install_bench >/dev/null
data="$here/../../shared/data/grids"
if [ $# -eq 0 ]; then set -- "$data/sphere_strong_d5.leaves" "$data/sphere_strong_d6.leaves" "$data/sphere_strong_d7.leaves"; fi
echo "machine: $(uname -n)"
echo "cpu:     $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //') ($(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg))"
echo "date:    $(date -u +%Y-%m-%dT%H:%M:%SZ)"
echo "times are process CPU seconds (one core); dual = Incidence + clipped_dual; peak = max RSS"
printf '%-26s %9s %9s %9s %9s %9s %9s %9s %8s\n' grid leaves cells hexes install dual sum us/leaf peakMB
for g in "$@"; do
  case "$g" in flat:*) args="--flat ${g#flat:}" ;; *) args="--grid $g" ;; esac
  # shellcheck disable=SC2086
  "$build/bench/install_bench" $args | awk '/^TABLE/ { printf "%-26s %9d %9d %9d %9.3f %9.3f %9.3f %9.2f %8.1f\n", $2, $3, $4, $5, $6, $7, $8, $9, $10 }'
done

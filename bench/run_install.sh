#!/bin/sh
# Times install (StrongRule) + clipped dual on the shared strongly balanced sphere grids (or
# the leaf files given), one process per grid so each peak memory is its own, and prints a
# table. Builds install_bench in the root build (Release, build/ unless BUILD_DIR is set).
#   bench/run_install.sh [GRID.leaves | flat:BASE ...]
# flat:BASE is the generated flat grid of levels BASE/BASE+1 (flat:6 1.18M leaves, flat:7 9.4M
# leaves, ~7 GB peak).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
bench_build install_bench
if [ $# -eq 0 ]; then set -- "$data/grids/sphere_strong_d5.leaves" "$data/grids/sphere_strong_d6.leaves" "$data/grids/sphere_strong_d7.leaves"; fi
bench_header
echo "times are process CPU seconds (one core); dual = Incidence + clipped_dual; peak = max RSS"
printf '%-26s %9s %9s %9s %9s %9s %9s %9s %8s\n' grid leaves cells hexes install dual sum us/leaf peakMB
for g in "$@"; do
  case "$g" in flat:*) args="--flat ${g#flat:}" ;; *) args="--grid $g" ;; esac
  # shellcheck disable=SC2086
  "$build/bench/install_bench" $args | awk '/^TABLE/ { printf "%-26s %9d %9d %9d %9.3f %9.3f %9.3f %9.2f %8.1f\n", $2, $3, $4, $5, $6, $7, $8, $9, $10 }'
done

#!/bin/sh
# Times the `dualhex mesh` pipeline per stage on the shared closed surfaces at several max
# depths, each case in its own process (so peak memory is per case), weak balance, and runs
# the strong balance too for its hex count. Builds mesh_stage_bench in the root build
# (Release, build/ unless BUILD_DIR is set). Not part of the test suite.
#   bench/run_mesh.sh [depth ...]          (default: 6 7 8; CASE_TIMEOUT seconds, default 600)
# Columns: times in ms (wall); ld = install + dual in thousands of clipped-dual hexes per
# second; extr = the core stage (selection + manifold repair); peak = max RSS of the weak case in MB; hexW / hexS = hexes of the final mesh with
# weak / strong balance; proj = pad + smoothing + optimiser + topology check + quality report.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
bench_build mesh_stage_bench
surfaces="$data/surfaces"
if [ $# -eq 0 ]; then set -- 6 7 8; fi
bench_header
printf '%-15s %2s %7s %7s %7s %6s %5s %5s %6s %6s %6s %5s %6s %5s %6s %7s %6s\n' model d leaves hexW hexS \
  octree bal pair install verify dual extr proj write total kHex/s peakMB
case_line() {  # model depth [--strong]: the TABLE line, or "FAILED reason"
  rc=0
  out=$(timeout "${CASE_TIMEOUT:-600}" "$build/bench/mesh_stage_bench" "$@" 2>&1) || rc=$?
  if [ "$rc" -ne 0 ]; then echo "FAILED (exit $rc, 124 = timeout) $(echo "$out" | tail -1)"; return; fi
  echo "$out" | grep '^TABLE'
}
for depth in "$@"; do
  for f in "$surfaces"/*; do
    weak=$(case_line "$f" --depth "$depth")
    strong=$(case_line "$f" --depth "$depth" --strong)
    name=$(basename "${f%.*}")
    case "$weak" in FAILED*) printf '%-15s %2s not run: %s\n' "$name" "$depth" "$weak"; continue ;; esac
    echo "$weak $strong" | awk '{ s = ($21 == "TABLE") ? $27 : "fail";
      printf "%-15s %2d %7d %7d %7s %6d %5d %5d %6d %6d %6d %5d %6d %5d %6d %7.0f %6.0f\n",
             $2, $3, $5, $7, s, $9, $10, $11, $12, $13, $14, $15, $16, $17, $18, $19 / 1000, $20 }'
  done
done

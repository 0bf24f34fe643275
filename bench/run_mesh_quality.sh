#!/bin/sh
# Independent mesh-quality benchmark (issue 12): meshes every shared surface with
# `dualhex mesh --preset P` (VTK into a temporary directory; extra `dualhex mesh` options
# from $MESH_OPTS) and measures each result with bench/mesh_quality (its own VTK reader,
# scaled Jacobian, topology and two-sided distance), then the four HybridOctree reference
# meshes (Tong et al. 2024) against the same gao_* surfaces, side by side. Those are in
# another frame (scaled ~100): measured with --fit (marked '*'; see mesh_quality.cpp).
# After each row: `dualhex mesh`'s exit code, its CPU seconds (user + sys, all threads), its
# peak resident memory, and the CPU seconds of each stage (its --json report's cpu_ms).
# Builds dualhex and mesh_quality in the root build (Release, build/ unless
# BUILD_DIR). Not part of the test suite.
#   bench/run_mesh_quality.sh [preset ...]  (coarse, medium, fine; default: medium)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build="${BUILD_DIR:-$here/../build}"
data="$here/../../shared/data"
cmake -S "$here/.." -B "$build" -DCMAKE_BUILD_TYPE=Release -DDUALHEX_BUILD_BENCH=ON >/dev/null
cmake --build "$build" -j2 --target dualhex mesh_quality >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ $# -eq 0 ]; then set -- medium; fi
echo "machine: $(uname -n), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg); date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
echo "commit:  $(git -C "$here/.." rev-parse --short HEAD 2>/dev/null || echo unknown)"
"$build/bench/mesh_quality" --header
measure() {  # mesh surface name [--fit]
  if [ "${4:-}" = "--fit" ]; then set -- --fit "$1" "$2" "$3"; fi
  "$build/bench/mesh_quality" "$@" 2>&1 || echo "$3 measurement failed"
}
stages() {  # the report's per-stage CPU seconds (all threads), in pipeline order
  python3 -c '
import json, sys
try:
    cpu = json.load(open(sys.argv[1]))["cpu_ms"]["all"]
except Exception:
    sys.exit(0)  # no report (the mesh failed): the line above says so
order = ["octree", "balance_pair", "install", "verify", "dual", "core", "refine", "pad", "features",
         "smooth", "optimise", "check", "report", "write"]
print("  stages (CPU s): " + ", ".join(f"{k} {cpu[k] / 1000:.2f}" for k in order if k in cpu))
' "$1"
}
for preset in "$@"; do
  for f in "$data"/surfaces/*; do
    name=$(basename "${f%.*}")
    out="$tmp/${name}_$preset.vtk"
    rc=0
    # shellcheck disable=SC2086  # MESH_OPTS is a list of options
    /usr/bin/time -f "%U %S %M" -o "$tmp/time" "$build/apps/dualhex" mesh "$f" -o "$out" --preset "$preset" \
      --json ${MESH_OPTS:-} >"$tmp/json" 2>"$tmp/log" || rc=$?
    if [ ! -f "$out" ]; then
      echo "$name $preset: dualhex mesh failed (exit $rc): $(tail -1 "$tmp/log")"
      continue
    fi
    measure "$out" "$f" "${name}_$preset"
    echo "  exit $rc, cpu $(tail -1 "$tmp/time" | awk "{printf \"%.2f s, peak RSS %.0f MB\", \$1 + \$2, \$3 / 1024}")"
    stages "$tmp/json"
  done
done
for f in "$data"/hex/hybridoctree_tong2024/*.vtk; do
  name=$(basename "${f%.vtk}")
  measure "$f" "$data/surfaces/gao_${name}_tri.off" "tong_$name" --fit
done

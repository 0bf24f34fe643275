#!/bin/sh
# Builds the grid benchmark in Release (standalone, in build-bench/) and runs it.
#   bench/run.sh [depth] [seed]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build="$here/../build-bench"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target grid_bench >/dev/null
echo "machine: $(uname -n)"
echo "cpu:     $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //') ($(nproc) cores)"
echo "date:    $(date -u +%Y-%m-%dT%H:%M:%SZ)"
"$build/grid_bench" "$@"

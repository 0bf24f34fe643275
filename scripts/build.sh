#!/usr/bin/env bash
# Usage: scripts/build.sh [BUILD_DIR] [extra cmake -D options...]
# Configures (Release by default) and builds dualhex with 2 parallel jobs: every target,
# or only those named in DUALHEX_TARGETS (space-separated, e.g. "dualhex").
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
shift || true
jobs="${DUALHEX_JOBS:-2}"
# ccache keys on paths relative to the checkout, so another clone of the repository (CI's)
# reuses the objects this one compiled.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${CMAKE_BUILD_TYPE:-Release}" "$@"
targets=()
for t in ${DUALHEX_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$build" -j"$jobs" "${targets[@]}"

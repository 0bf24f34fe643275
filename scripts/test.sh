#!/usr/bin/env bash
# The test suite: install what is missing, build (build/ unless a directory is given),
# run every test with ctest. Exits non-zero on any failure.
# Usage: scripts/test.sh [BUILD_DIR] [extra cmake -D options...]
# DUALHEX_CTEST_EXCLUDE (unset by default): a ctest -E regex of tests to leave out
# (.ci/run's sanitizer pass uses it for the long end-to-end repeats).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
shift || true
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$build" "$@"
cd "$build"
exclude=()
if [ -n "${DUALHEX_CTEST_EXCLUDE:-}" ]; then exclude=(-E "$DUALHEX_CTEST_EXCLUDE"); fi
ctest --output-on-failure -j"${DUALHEX_JOBS:-2}" "${exclude[@]}"

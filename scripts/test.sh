#!/usr/bin/env bash
# The test suite: install what is missing, build (build/ unless a directory is given),
# run every test with ctest. Exits non-zero on any failure.
# Usage: scripts/test.sh [BUILD_DIR] [extra cmake -D options...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
shift || true
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$build" "$@"
cd "$build"
ctest --output-on-failure -j"${DUALHEX_JOBS:-2}"

#!/usr/bin/env bash
# The main job: install what is missing, build the `dualhex` program only (Release, build/;
# scripts/test.sh builds the rest and reuses this), put it on PATH as a symlink
# $DUALHEX_BIN_DIR/dualhex -> build/apps/dualhex (default /usr/local/bin, when writable),
# run `dualhex verify`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
DUALHEX_TARGETS=dualhex "$root/scripts/build.sh" "$root/build"
exe="$root/build/apps/dualhex"
bin="${DUALHEX_BIN_DIR:-/usr/local/bin}"
if [ -d "$bin" ] && [ -w "$bin" ]; then
  ln -sf "$exe" "$bin/dualhex"
  echo "dualhex is on PATH: $bin/dualhex -> $exe"
else
  echo "dualhex is $exe (add $root/build/apps to PATH)"
fi
exec "$exe" verify "$@"

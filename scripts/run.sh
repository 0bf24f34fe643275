#!/usr/bin/env bash
# The main job: install what is missing, build (Release, build/), run `dualhex verify`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$root/build"
exec "$root/build/apps/dualhex" verify "$@"

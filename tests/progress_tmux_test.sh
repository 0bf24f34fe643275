#!/usr/bin/env bash
# The progress bar in a real terminal (tmux, 120x30), for `dualhex mesh`:
#   bar       a percentage bar appears while it runs; the final screen holds the one-line
#             summary and no leftover bar.
#   redirect  stderr redirected to a file (stdout still the terminal): the file is empty
#             (no bar, no summary, no '\r'), as before progress bars existed; nothing of a
#             bar on the screen either. The same under --json with stderr the terminal.
# Usage: progress_tmux_test.sh DUALHEX_EXE SCRATCH_DIR MODE. Exit 77 (CTest skip) only if
# tmux is missing.
set -euo pipefail
exe="$1" scratch="$2" mode="$3"
command -v tmux >/dev/null 2>&1 || { echo "tmux not installed: skipped"; exit 77; }
rm -rf "$scratch" && mkdir -p "$scratch"
socket="dualhex_progress_$$"  # a private tmux server: no other session is touched
trap 'tmux -L "$socket" kill-server >/dev/null 2>&1 || true' EXIT
bar_re='\] [0-9]+% \|[#.]+\| [0-9]+\.[0-9] s'

fail() { echo "FAIL: $*"; echo "--- last screen:"; cat "$scratch/screen" 2>/dev/null || true; exit 1; }

# Runs "$@" (a shell command line) in a fresh 120x30 session; polls the screen every 0.05 s
# until the command has printed DONE=<exit code>; leaves the last screen in $scratch/screen
# and in $scratch/seen every screen that showed a bar. Timeout 600 s (the sanitizer build).
run_in_terminal() {
    : >"$scratch/seen"
    tmux -L "$socket" -f /dev/null new-session -d -s t -x 120 -y 30 "$1; echo DONE=\$?; sleep 600"
    local i
    for ((i = 0; i < 12000; ++i)); do
        tmux -L "$socket" capture-pane -p -t t >"$scratch/screen"
        if grep -Eq "$bar_re" "$scratch/screen"; then cat "$scratch/screen" >>"$scratch/seen"; fi
        grep -q '^DONE=' "$scratch/screen" && break
        sleep 0.05
    done
    tmux -L "$socket" kill-session -t t
    grep -q '^DONE=' "$scratch/screen" || fail "the command did not finish in 600 s"
}

q() { printf '%q' "$1"; }

case "$mode" in
bar)
    run_in_terminal "$(q "$exe") mesh -o $(q "$scratch/m.vtk")"
    grep -q '^DONE=0' "$scratch/screen" || fail "dualhex mesh failed"
    [[ -s "$scratch/seen" ]] || fail "no percentage bar was seen while it ran"
    grep -Eq "\[mesh [0-9]+/[0-9]+: [a-z]+$bar_re" "$scratch/seen" || fail "the bar does not name a mesh stage"
    grep -Eq "^mesh: [0-9,]+ hexes written to .*m\.vtk in [0-9]+\.[0-9] s$" "$scratch/screen" ||
        fail "no summary line on the final screen"
    if grep -Eq '[0-9]+% \|' "$scratch/screen"; then fail "a bar is left on the final screen"; fi
    grep -q '^wrote ' "$scratch/screen" || fail "the report (stdout) is missing"
    ;;
redirect)
    run_in_terminal "$(q "$exe") mesh --preset coarse -o $(q "$scratch/m.vtk") 2>$(q "$scratch/err")"
    grep -q '^DONE=0' "$scratch/screen" || fail "dualhex mesh failed"
    [[ ! -s "$scratch/err" ]] || { echo "--- stderr:"; cat -A "$scratch/err"; fail "stderr (a file) is not empty"; }
    [[ ! -s "$scratch/seen" ]] || fail "a bar appeared on the terminal"
    grep -q '^wrote ' "$scratch/screen" || fail "the report (stdout) is missing"
    run_in_terminal "$(q "$exe") mesh --preset coarse --json --force -o $(q "$scratch/m.vtk") >$(q "$scratch/json")"
    grep -q '^DONE=0' "$scratch/screen" || fail "dualhex mesh --json failed"
    [[ ! -s "$scratch/seen" ]] || fail "a bar appeared under --json"
    if grep -Eq '^mesh: .* hexes written' "$scratch/screen"; then fail "a summary line appeared under --json"; fi
    head -c1 "$scratch/json" | grep -q '{' || fail "--json output is not JSON"
    ;;
*)
    echo "unknown mode $mode"; exit 2 ;;
esac
echo "PASS ($mode)"

#!/bin/sh
# Runs each reader's libFuzzer harness (tests/fuzz, built when DUALHEX_FUZZ finds clang with
# -fsanitize=fuzzer) for SECONDS each (default 300) and reports executions, corpus size and
# findings (crash-/leak-/timeout-/oom- artifacts, kept in BUILD/fuzz/<reader>/). Not a test.
#   bench/run_fuzz_readers.sh [SECONDS] [BUILD_DIR]
set -eu
seconds=${1:-300}
build=${2:-build}
cmake --build "$build" -j2 --target fuzz_obj fuzz_off fuzz_stl fuzz_ply fuzz_leaves >/dev/null
total=0
for reader in obj off stl ply leaves; do
    dir="$build/tests/fuzz/$reader"
    exe="$build/tests/fuzz/fuzz_$reader"
    [ -x "$exe" ] || { echo "fuzz_$reader: not built (DUALHEX_FUZZ off or no clang libFuzzer)"; exit 1; }
    mkdir -p "$dir/corpus"
    log="$dir/run.log"
    set +e
    "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
        -artifact_prefix="$dir/" "$dir/corpus" "$dir/seeds" >"$log" 2>&1
    rc=$?
    set -e
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    per_s=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    findings=$(find "$dir" -maxdepth 1 \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
    corpus=$(find "$dir/corpus" -type f | wc -l)
    echo "fuzz_$reader: ${seconds}s, ${execs:-?} executions (${per_s:-?}/s), corpus $corpus, findings $findings, exit $rc"
    [ "$findings" -eq 0 ] || find "$dir" -maxdepth 1 \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \)
    total=$((total + findings))
done
echo "total findings: $total"
[ "$total" -eq 0 ]

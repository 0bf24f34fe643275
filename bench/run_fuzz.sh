#!/bin/sh
# Runs the proof checker's libFuzzer harness for SECONDS (default 600) and reports executions
# and findings. Usage: bench/run_fuzz.sh [SECONDS] [BUILD_DIR]   (BUILD_DIR default: build)
# Needs a build configured with DUALHEX_FUZZ=ON (automatic where clang++ -fsanitize=fuzzer works).
set -eu
seconds=${1:-600}
build=${2:-build}
cmake --build "$build" --target dualhex-checker-fuzz
dir="$build/proofs"
log="$dir/fuzz-run.log"
"$dir/dualhex-checker-fuzz" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
  -print_final_stats=1 -artifact_prefix="$dir/fuzz-artifacts/" "$dir/fuzz-corpus" "$dir/fuzz-seeds" >"$log" 2>&1 || true
grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^Done" "$log" || tail -n 5 "$log"
echo "corpus: $(ls "$dir/fuzz-corpus" | wc -l) inputs; findings: $(ls "$dir/fuzz-artifacts" | wc -l) in $dir/fuzz-artifacts (log: $log)"

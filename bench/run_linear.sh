#!/bin/sh
# Is install + clipped dual linear in the number of leaves? Times the generated flat grids
# of bench/install_bench (levels BASE/BASE+1, StrongRule: 18,432 / 147,456 / 1,179,648 /
# 9,437,184 leaves for BASE 4..7), each run in its own process, median of REPS (default 3)
# runs of process CPU time per leaf, and prints the max/min ratio over the sizes.
#
# Two allocator settings: glibc's default, and glibc told to keep freed memory
# (mmap_max=0, trim_threshold=64 GiB: blocks above 32 MB are not mmap'd afresh, so every big
# temporary array does not cost new page faults and zeroed pages; README "Figures").
# Builds install_bench (Release, build/ unless BUILD_DIR is set). Not part of the test suite.
#   bench/run_linear.sh [BASE ...]        (default: 4 5 6 7; flat:7 needs ~8 GB, ~30 s a run)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
reps="${REPS:-3}"
bench_build install_bench
if [ $# -eq 0 ]; then set -- 4 5 6 7; fi
keep="glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=68719476736"
bench_header
echo "install + dual (Incidence + clipped dual), process CPU time, median of $reps; peak = max RSS"
median_run() {  # tunables base: "leaves us_per_leaf peak_MB", the run with the median us/leaf
  i=0
  while [ "$i" -lt "$reps" ]; do
    GLIBC_TUNABLES="$1" "$build/bench/install_bench" --flat "$2" | awk '/^TABLE/ { print $3, $9, $10 }'
    i=$((i + 1))
  done | sort -k2 -g | awk -v m=$(((reps + 1) / 2)) 'NR == m'
}
for alloc in default keep-freed; do
  tunables=""
  [ "$alloc" = keep-freed ] && tunables="$keep"
  echo
  echo "allocator: $alloc"
  printf '%10s %9s %8s\n' leaves us/leaf peakMB
  for base in "$@"; do median_run "$tunables" "$base"; done |
    awk '{ printf "%10d %9.2f %8.0f\n", $1, $2, $3; if (NR == 1 || $2 < lo) lo = $2; if ($2 > hi) hi = $2 }
         END { printf "max/min time per leaf: %.2f\n", hi / lo }'
done

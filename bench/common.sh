# Sourced by the bench/run_*.sh scripts (POSIX sh): where the build is, how to build one
# benchmark target, and the header every table starts with (figures mean nothing without
# the machine, its load and the date).
#   . "$here/common.sh"; bench_build TARGET; bench_header
build="${BUILD_DIR:-$here/../build}"
data="$here/../../shared/data"

bench_build() {  # target: configures build/ (Release, benchmarks on) and builds the target
  cmake -S "$here/.." -B "$build" -DCMAKE_BUILD_TYPE=Release -DDUALHEX_BUILD_BENCH=ON >/dev/null
  cmake --build "$build" -j2 --target "$1" >/dev/null
}

bench_header() {
  echo "machine: $(uname -n)"
  echo "cpu:     $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //') ($(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg))"
  echo "date:    $(date -u +%Y-%m-%dT%H:%M:%SZ)"
}

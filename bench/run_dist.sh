#!/bin/sh
# Strong and weak scaling of dualhex-dist (distributed/) under mpirun on this machine.
#   bench/run_dist.sh [NP_MAX]      (default 4; --oversubscribe: ranks may outnumber cores)
# Strong: sphere_weak_d7 (152,832 leaves) on 1..NP_MAX ranks. Weak: slab grids, level 5 with
# np*8 of its 32 x-slabs refined once (32,768 + np*57,344 leaves), on np ranks. One table
# row per run: wall ms (rank 0: read, forest, mesh, total), the largest rank's leaves,
# ghosts, context points sent and bytes exchanged, peak RSS. Not a test.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build="${BUILD_DIR:-$here/../build}"
cmake -S "$here/.." -B "$build" -DCMAKE_BUILD_TYPE=Release -DDUALHEX_WITH_P4EST=ON >/dev/null
cmake --build "$build" -j2 --target dualhex-dist >/dev/null
exe="$build/distributed/dualhex-dist"
npmax="${1:-4}"
data="$here/../../shared/data/grids"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

slab() {  # slab N > file: level 5, the first N x-slabs refined once
  awk -v n="$1" 'BEGIN { for (i = 0; i < 32; i++) for (j = 0; j < 32; j++) for (k = 0; k < 32; k++)
    if (i < n) { for (c = 0; c < 8; c++) print 6, 2*i + c%2, 2*j + int(c/2)%2, 2*k + int(c/4) }
    else print 5, i, j, k }'
}

row() {  # row LABEL NP GRID BALANCE
  mpirun --oversubscribe -np "$2" "$exe" "$3" --balance "$4" --json > "$tmp/out.json"
  python3 - "$1" "$tmp/out.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[2]))
r = d["per_rank"]
mx = lambda k: max(x[k] for x in r)
print("%-14s %3d %9d %9d %8d %9d %10d %8.0f %8.0f %8.0f %8.0f %8.1f" % (
    sys.argv[1], d["ranks"], d["leaves"], mx("local_leaves"), mx("ghost_leaves"), mx("points_remote"),
    mx("bytes_sent") + mx("bytes_received"), d["ms"]["read"], d["ms"]["forest"], d["ms"]["mesh"],
    d["ms"]["total"], mx("peak_rss_kb") / 1024.0))
PY
}

echo "machine: $(uname -n), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg), $(date -u +%Y-%m-%dT%H:%M:%SZ)"
echo "wall ms on rank 0; max over ranks for leaves, ghosts, remote points, bytes (sent + received), peak RSS MB"
printf '%-14s %3s %9s %9s %8s %9s %10s %8s %8s %8s %8s %8s\n' run np leaves maxlocal maxghost remotepts bytes read forest mesh total peakMB
np=1
while [ "$np" -le "$npmax" ]; do row strong:d7 "$np" "$data/sphere_weak_d7.leaves" weak; np=$((np + 1)); done
np=1
while [ "$np" -le "$npmax" ]; do slab $((np * 8)) > "$tmp/slab.leaves"; row weak:slab "$np" "$tmp/slab.leaves" strong; np=$((np + 1)); done

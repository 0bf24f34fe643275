#!/bin/sh
# Strong and weak scaling of dualhex-dist (distributed/) under mpirun on this machine.
#   bench/run_dist.sh [NP_MAX]      (default 4; --oversubscribe: ranks may outnumber cores)
# Strong: sphere_weak_d7 (152,832 leaves) on 1..NP_MAX ranks, read in byte ranges; the
# bunny (--surface, --preset medium) on 1..NP_MAX ranks. Weak: slab grids, level 5 with
# np*8 of its 32 x-slabs refined once (32,768 + np*57,344 leaves), on np ranks. One table
# row per run: the largest rank's leaves, ghosts, context points and bytes exchanged,
# bytes of the input it read (leaf files), CPU seconds (user + sys, getrusage), peak RSS
# after reading, after the forest (balanced, paired) and at the end; wall ms of rank 0.
# Not a test.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build="${BUILD_DIR:-$here/../build}"
cmake -S "$here/.." -B "$build" -DCMAKE_BUILD_TYPE=Release -DDUALHEX_WITH_P4EST=ON >/dev/null
cmake --build "$build" -j2 --target dualhex-dist >/dev/null
exe="$build/distributed/dualhex-dist"
npmax="${1:-4}"
data="$here/../../shared/data"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

slab() {  # slab N > file: level 5, the first N x-slabs refined once
  awk -v n="$1" 'BEGIN { for (i = 0; i < 32; i++) for (j = 0; j < 32; j++) for (k = 0; k < 32; k++)
    if (i < n) { for (c = 0; c < 8; c++) print 6, 2*i + c%2, 2*j + int(c/2)%2, 2*k + int(c/4) }
    else print 5, i, j, k }'
}

row() {  # row LABEL NP ARGS...
  label=$1 np=$2
  shift 2
  mpirun --oversubscribe -np "$np" "$exe" "$@" --json > "$tmp/out.json" 2>/dev/null
  python3 - "$label" "$tmp/out.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[2]))
r = d["per_rank"]
mx = lambda f: max(f(x) for x in r)
mb = lambda f: mx(f) / 1024.0
print("%-13s %2d %8d %8d %6d %8d %9d %9d %6.2f %6.1f %6.1f %6.1f %7.0f %s" % (
    sys.argv[1], d["ranks"], d["leaves"], mx(lambda x: x["local_leaves"]), mx(lambda x: x["ghost_leaves"]),
    mx(lambda x: x["points_remote"]), mx(lambda x: x["bytes_sent"] + x["bytes_received"]),
    mx(lambda x: x["input"].get("bytes_read", 0)), mx(lambda x: x["cpu_ms"]) / 1e3,
    mb(lambda x: x["input"]["peak_rss_kb_read"]), mb(lambda x: x["peak_rss_kb_forest"]), mb(lambda x: x["peak_rss_kb"]),
    d["ms"]["total"],
    d["summary"]["hex_hash"]))
PY
}

echo "machine: $(uname -n), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg), $(date -u +%Y-%m-%dT%H:%M:%SZ)"
echo "max over ranks: local leaves, ghosts, remote context points, context bytes (sent + received), input bytes read,"
echo "CPU s (user + sys), peak RSS MB after read / forest / end; wall ms of rank 0 (loaded machine: not a speedup)"
printf '%-13s %2s %8s %8s %6s %8s %9s %9s %6s %6s %6s %6s %7s %s\n' run np leaves maxlocal ghost remote ctxbytes readbytes cpu_s rdMB frMB endMB wallms hexhash
np=1
while [ "$np" -le "$npmax" ]; do row strong:d7 "$np" "$data/grids/sphere_weak_d7.leaves" --balance weak; np=$((np + 1)); done
np=1
while [ "$np" -le "$npmax" ]; do
  row strong:bunny "$np" --surface "$data/surfaces/gao_bunny_tri.off" --preset medium; np=$((np + 1))
done
np=1
while [ "$np" -le "$npmax" ]; do
  slab $((np * 8)) > "$tmp/slab.leaves"; row weak:slab "$np" "$tmp/slab.leaves" --balance strong; np=$((np + 1))
done

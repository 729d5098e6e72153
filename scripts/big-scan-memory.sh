#!/bin/bash
# Peak memory and wall time of `sgtllc pair` and `sgtllc label` on a 10 M-point scan made from the bundled KITTI 00
# scans (data/kitti/00): the four scans and their labels repeated with an offset of SPREAD m per copy (on a 10 × N
# grid) until N_POINTS points. Nothing is asserted; BENCHMARKS.md "Memory on big inputs" lists the results.
#   scripts/big-scan-memory.sh build/apps/sgtllc/sgtllc [N_POINTS] [SPREAD]
set -euo pipefail
cli=${1:?usage: big-scan-memory.sh SGTLLC_BINARY [N_POINTS] [SPREAD]}
points=${2:-10000000}
spread=${3:-0.013}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 - "$root/data/kitti/00" "$work/big" "$points" "$spread" <<'PY'
import glob, sys
import numpy as np
src, out, n_target, spread = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4])
bins = sorted(glob.glob(src + "/velodyne/*.bin"))
points, labels, total, k = [], [], 0, 0
while total < n_target:
    b = bins[k % len(bins)]
    p = np.fromfile(b, dtype=np.float32).reshape(-1, 4).copy()
    p[:, 0] += spread * (k % 10)
    p[:, 1] += spread * (k // 10)
    points.append(p)
    labels.append(np.fromfile(b.replace("velodyne", "labels").replace(".bin", ".label"), dtype=np.uint32))
    total += len(p)
    k += 1
np.concatenate(points)[:n_target].tofile(out + ".bin")
np.concatenate(labels)[:n_target].tofile(out + ".label")
PY
echo "scan: $points points ($(stat -c %s "$work/big.bin") bytes + $(stat -c %s "$work/big.label") bytes of labels)"
measure() {
  local name=$1
  shift
  /usr/bin/time -v "$@" > /dev/null 2> "$work/time"
  local kb wall
  kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time")
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time")
  echo "$name: peak $((kb / 1024)) MiB ($((kb * 1024 / points)) bytes a point in all), wall $wall"
}
measure pair "$cli" pair "$work/big.bin" "$root/data/kitti/00/velodyne/000052.bin" --labels-query "$work/big.label" --json
measure label "$cli" label "$work/big.bin" --out "$work/out.label" --force

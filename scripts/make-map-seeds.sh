#!/bin/sh
# Writes fuzz/seeds/map/ with the given sgtllc: two 3-frame maps of fixed synthetic node files (8 nodes per frame,
# SemanticKITTI ids of the seven paper classes), one without poses and one with them (`--odometry`), and a 3-frame
# map of scans (the first 3,000 points of the bundled KITTI scans 52, 88 and 850) with small footprints (FTPR), and
# the posed map with the same frames merged in as a second session (SESS). Run it whenever the map format
# version changes (docs/map-format.md, "Versions"), so the fuzzer starts from files this build reads.
#   scripts/make-map-seeds.sh build/apps/sgtllc/sgtllc
set -eu
cli=${1:?usage: make-map-seeds.sh SGTLLC_BINARY}
out=$(dirname "$0")/../fuzz/seeds/map
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/nodes"
for f in 0 1 2; do
  awk -v f="$f" 'BEGIN { split("50 51 70 71 72 80 81", id); for (k = 0; k < 8; ++k) printf "%.3f %.3f %.3f %d\n", 3 * k - 10 + f, 7 - 2 * k, 0.5 * (k % 3), id[k % 7 + 1] }' \
    > "$work/nodes/00000$f.txt"
done
printf '1 0 0 %d 0 1 0 0 0 0 1 0\n' 0 1 2 > "$work/poses.txt"
printf 'Tr: 1 0 0 0 0 1 0 0 0 0 1 0\n' > "$work/calib.txt"
"$cli" run --nodes "$work/nodes" --save-map "$out/three_frames.sgtmap" --force > /dev/null 2>&1
"$cli" run --nodes "$work/nodes" --odometry "$work/poses.txt" --calib "$work/calib.txt" \
  --save-map "$out/three_frames_poses.sgtmap" --force > /dev/null 2>&1 2>&1
# Sessions: nodes off a line (a relocalized frame needs inlier centres that fix the rotation), a map of them, the
# same frames merged in again as a second session.
mkdir -p "$work/spread"
for f in 0 1 2; do
  awk -v f="$f" 'BEGIN { split("50 51 70 71 72 80 81", id); for (k = 0; k < 10; ++k) printf "%.3f %.3f %.3f %d\n", 3 * k - 12 + f, (k * k * 7) % 11 - 5, 0.5 * (k % 3), id[k % 7 + 1] }' \
    > "$work/spread/00000$f.txt"
done
printf 'backend:\n  sessions:\n    min_inter_loops: 1\n    keep_distance_m: 0\n' > "$work/one.yaml"
"$cli" run --nodes "$work/spread" --odometry "$work/poses.txt" --calib "$work/calib.txt" --save-map "$work/spread.sgtmap" \
  > /dev/null 2>&1
"$cli" run --nodes "$work/spread" --odometry "$work/poses.txt" --calib "$work/calib.txt" --config "$work/one.yaml" \
  --map "$work/spread.sgtmap" --session-name again --save-map "$out/two_sessions.sgtmap" --force > /dev/null 2>&1
here=$(dirname "$0")/..
mkdir -p "$work/scans/velodyne" "$work/scans/labels"
k=0
for f in 000052 000088 000850; do
  head -c 48000 "$here/data/kitti/00/velodyne/$f.bin" > "$work/scans/velodyne/00000$k.bin"
  head -c 12000 "$here/data/kitti/00/labels/$f.label" > "$work/scans/labels/00000$k.label"
  k=$((k + 1))
done
# 5 m footprints of 1 m cells: 100 bits a frame, so the seed stays small.
printf 'verification:\n  footprint_radius: 5\n  footprint_cell: 1\n' > "$work/small.yaml"
"$cli" run "$work/scans" --config "$work/small.yaml" --save-map "$out/three_scans_footprints.sgtmap" --force > /dev/null 2>&1
"$cli" map info "$out/three_frames_poses.sgtmap" | head -3
"$cli" map info "$out/three_scans_footprints.sgtmap" | head -4
"$cli" map info "$out/two_sessions.sgtmap" | sed -n 2,8p

#!/bin/sh
# Runs the libFuzzer harnesses of fuzz/ (README "Reliability checks"): first every saved reproducer of
# fuzz/regressions/HARNESS/ once, then each harness for SECONDS from its seeds. Usage (from `make fuzz`):
#   fuzz/run.sh BUILD_DIR SECONDS [HARNESS...]      (default: every harness built in BUILD_DIR/fuzz)
# New corpus entries go to BUILD_DIR/corpus/HARNESS (kept between runs); a finding leaves its reproducer in
# BUILD_DIR/findings/HARNESS/ and makes the script fail. Memory limits: a reader that allocates more than 2 GB
# for an input of a few kilobytes is a finding (an input cannot make a reader take the machine's memory).
set -eu
cd "$(dirname "$0")/.."
build=$1
seconds=$2
shift 2
harnesses=${*:-$(cd "$build/fuzz" && find . -maxdepth 1 -type f -name 'fuzz_*' -perm -u+x | sed 's|^\./fuzz_||' | sort)}
seeds=$build/seeds
export SGTLLC_FUZZ_TMPDIR="${SGTLLC_FUZZ_TMPDIR:-/dev/shm}"
[ -d "$SGTLLC_FUZZ_TMPDIR" ] || SGTLLC_FUZZ_TMPDIR=${TMPDIR:-/tmp}
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"

# Seeds derived from data/ (the real samples; kept small so that each execution stays fast).
rm -rf "$seeds"
mkdir -p "$seeds/kitti_scan" "$seeds/kitti_poses"
for f in 000052 004501; do
  # Byte 0 = 204 splits the rest 1024 : 256, i.e. the first 64 points of the scan and their 64 labels.
  { printf '\314'; head -c 1024 "data/kitti/00/velodyne/$f.bin"; head -c 256 "data/kitti/00/labels/$f.label"; } \
    > "$seeds/kitti_scan/$f"
done
# One-byte labels (data/nuscenes): byte 0 = 240 splits the rest 1024 : 64, 64 points and their 64 label bytes.
for f in 0001/000000 0006/000000; do
  { printf '\360'; head -c 1024 "data/nuscenes/${f%/*}/velodyne/${f#*/}.bin";
    head -c 64 "data/nuscenes/${f%/*}/labels/${f#*/}.label"; } > "$seeds/kitti_scan/nuscenes_${f%/*}"
done
head -n 3 data/kitti/00/poses.txt > "$seeds/kitti_poses/poses_head.txt"
cp data/kitti/00/calib.txt "$seeds/kitti_poses/calib.txt"
# Trajectories: the first poses of the KITTI and TUM excerpts, alone (byte 0 even) and after KITTI 00's calib
# (byte 0 = 2·s + 1 splits the rest at s/127 of its length; the calib is padded with newlines to end there).
mkdir -p "$seeds/trajectory"
odo=data/kitti/00/odometry
for f in kissicp_first1000_kitti kissicp_first1000_tum semantickitti_poses_first1000; do
  head -n 3 "$odo/$f.txt" > "$seeds/trajectory/$f.body"
  { printf '\000'; cat "$seeds/trajectory/$f.body"; } > "$seeds/trajectory/$f"
  calib_len=$(wc -c < data/kitti/00/calib.txt)
  body_len=$(wc -c < "$seeds/trajectory/$f.body")
  s=$(( (127 * calib_len + calib_len + body_len - 1) / (calib_len + body_len) ))
  pad=0
  while [ $(( (calib_len + pad + body_len) * s / 127 )) -ne $(( calib_len + pad )) ]; do pad=$((pad + 1)); done
  { printf "\\$(printf '%03o' $((2 * s + 1)))"; cat data/kitti/00/calib.txt; head -c "$pad" /dev/zero | tr '\0' '\n'
    cat "$seeds/trajectory/$f.body"; } > "$seeds/trajectory/${f}_calib"
  rm "$seeds/trajectory/$f.body"
done
extra_seeds() {
  case $1 in
    pcd) echo data/pcd ;;
    config_yaml) echo configs ;;
    *) ;;
  esac
}

status=0
for h in $harnesses; do
  bin=$build/fuzz/fuzz_$h
  corpus=$build/corpus/$h
  findings=$build/findings/$h
  mkdir -p "$corpus" "$findings" "$seeds/$h"
  flags="-rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=10 -artifact_prefix=$findings/"
  if [ -d "fuzz/regressions/$h" ] && [ -n "$(ls "fuzz/regressions/$h")" ]; then
    echo "== fuzz_$h: reproducers in fuzz/regressions/$h"
    # shellcheck disable=SC2086
    "$bin" $flags fuzz/regressions/$h/* || status=1
  fi
  echo "== fuzz_$h: ${seconds} s"
  # shellcheck disable=SC2046,SC2086
  if ! "$bin" $flags -max_total_time="$seconds" -print_final_stats=1 "$corpus" "$seeds/$h" \
       $([ -d "fuzz/seeds/$h" ] && echo "fuzz/seeds/$h") $(extra_seeds "$h") > "$build/fuzz_$h.log" 2>&1; then
    status=1
    tail -n 60 "$build/fuzz_$h.log"
  fi
  grep -E "^stat::number_of_executed_units|^#[0-9]+.*DONE" "$build/fuzz_$h.log" | tail -n 2 || true
done
exit $status

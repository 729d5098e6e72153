#!/bin/sh
# The threaded paths, run by check.sh under TSan: the test programs named (Makefile TSAN_TESTS: the suites that run
# parallelFor at two threads), then the command-line tool's run, eval and simulate with --threads 2 on the small
# real samples of data/ and a small simulated sequence.
#   scripts/sanitize/tsan-paths.sh BUILD_DIR TEST...
set -eu
build=$1
shift
cd "$(dirname "$0")/../.."
status=0
for t in "$@"; do
  echo "== $t"
  "$build/tests/$t" --gtest_brief=1 || status=1
done

sgtllc=$build/apps/sgtllc/sgtllc
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '4501 52 1\n850 88 0\n52 88 0\n' > "$tmp/pairs.txt"
cli() {
  echo "== sgtllc $*"
  "$sgtllc" "$@" > "$tmp/out.txt" 2>&1 || { cat "$tmp/out.txt"; status=1; }
}
cli run data/kitti/00 --threads 2 --out "$tmp/loops.csv"
cli eval data/kitti/00 --threads 2
cli eval data/kitti/00 --pairs "$tmp/pairs.txt" --threads 2 --report "$tmp/report"
cli simulate --out "$tmp/sim" --frames 6 --seed 3 --threads 2
cli eval "$tmp/sim" --threads 2
exit $status

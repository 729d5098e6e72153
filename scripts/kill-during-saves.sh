#!/bin/bash
# Kills `sgtllc simulate` with SIGKILL at a random moment of each of ten runs (each writes ~N scans, poses and
# labels, every file through a temporary file and a rename: include/sgtllc/io/output_file.h) and checks that no
# file under a final name is partial: each is byte-identical to the same file of a complete run. A killed process
# cannot remove its temporary file, so hidden `.NAME.sgtllc-tmp-XXXXXXXXXXXX` leftovers are counted, and anything
# else hidden is an error.
#   scripts/kill-during-saves.sh build/apps/sgtllc/sgtllc [FRAMES]
set -euo pipefail
cli=${1:?usage: kill-during-saves.sh SGTLLC_BINARY [FRAMES]}
frames=${2:-30}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
now_ms() { echo $(( $(date +%s%N) / 1000000 )); }
# The complete run, timed: the kills fall between its first written file and its end, when saves are under way.
start=$(now_ms)
"$cli" simulate --out "$work/ref" --frames "$frames" --seed 3 --no-preview --threads 1 > /dev/null 2>&1 &
pid=$!
first_ms=""
while kill -0 "$pid" 2> /dev/null; do
  if [ -z "$first_ms" ] && [ -n "$(find "$work/ref" -type f 2> /dev/null | head -1)" ]; then first_ms=$(( $(now_ms) - start )); fi
  sleep 0.02
done
wait "$pid"
span_ms=$(( $(now_ms) - start ))
first_ms=${first_ms:-0}
echo "complete run: ${span_ms} ms, first file after ${first_ms} ms, $(find "$work/ref" -type f | wc -l) files"
failures=0
RANDOM=7
for run in $(seq 1 10); do
  dir="$work/run$run"
  delay_ms=$(( first_ms + (span_ms - first_ms) * (RANDOM % 100) / 100 ))
  "$cli" simulate --out "$dir" --frames "$frames" --seed 3 --no-preview --threads 1 > /dev/null 2>&1 &
  pid=$!
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -9 "$pid" 2> /dev/null || true
  wait "$pid" 2> /dev/null || true
  complete=0
  while IFS= read -r -d '' f; do
    rel=${f#"$dir"/}
    if cmp -s "$f" "$work/ref/$rel"; then
      complete=$((complete + 1))
    else
      echo "run $run: PARTIAL or different file under a final name: $rel"
      failures=$((failures + 1))
    fi
  done < <(find "$dir" -type f ! -name '.*' -print0 2> /dev/null || true)
  leftovers=$( (find "$dir" -type f -name '.*.sgtllc-tmp-*' 2> /dev/null || true) | wc -l)
  strays=$( (find "$dir" -type f -name '.*' ! -name '.*.sgtllc-tmp-*' 2> /dev/null || true) | wc -l)
  if [ "$strays" -ne 0 ]; then
    echo "run $run: $strays hidden files that are not temporary files"
    failures=$((failures + 1))
  fi
  echo "run $run: killed after ${delay_ms} ms: $complete complete files, $leftovers leftover temporary files"
done
if [ "$failures" -ne 0 ]; then
  echo "kill-during-saves: $failures failures"
  exit 1
fi
echo "kill-during-saves: 10 runs killed, no partial file under a final name"

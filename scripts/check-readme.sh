#!/bin/sh
# Runs the README's runnable shell blocks as written, against a built sgtllc, and fails if any command fails.
#
#   scripts/check-readme.sh [--list] [MARKDOWN [SGTLLC]]     (defaults: README.md, build/apps/sgtllc/sgtllc)
#
# A block is runnable when the line just before its ```sh fence is the comment <!-- check -->. Each marked block
# runs on its own with `sh -e` in a fresh scratch folder that holds links to the repository's top-level entries
# (data/, configs/, ...; a README command uses the bundled data only, never anything outside the repository),
# and with `sgtllc` on PATH as the given binary: relative paths work as in a clone, outputs land in the scratch
# folder. Lines starting with # are comments (expected output in the README), as in any shell.
# --list prints the marked blocks (file line and text) instead of running them.
# A file without any marked block fails: that is almost always a lost marker, not a README without commands.
set -eu

list=0
if [ "${1:-}" = "--list" ]; then
  list=1
  shift
fi
repo=$(cd "$(dirname "$0")/.." && pwd)
markdown=${1:-$repo/README.md}
cli=${2:-$repo/build/apps/sgtllc/sgtllc}
[ -f "$markdown" ] || { echo "check-readme: $markdown: no such file" >&2; exit 1; }
case $markdown in /*) ;; *) markdown=$(pwd)/$markdown ;; esac
if [ "$list" -eq 0 ]; then
  [ -x "$cli" ] || { echo "check-readme: $cli: not an executable (build it: make build TARGETS=sgtllc_cli)" >&2; exit 1; }
  case $cli in /*) ;; *) cli=$(pwd)/$cli ;; esac
fi

scratch=$(mktemp -d "${TMPDIR:-/tmp}/sgtllc-readme.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
# One file per marked block: blocks/NNNN holds the block's text, its first line the README line of the fence.
mkdir "$scratch/blocks"
awk -v out="$scratch/blocks" '
  /^<!-- check -->[ \t]*$/ { marked = NR; next }
  inblock && /^```/ { inblock = 0; close(file); next }
  inblock { print > file; next }
  /^```(sh|bash|shell)[ \t]*$/ && marked == NR - 1 {
    inblock = 1; n++; file = sprintf("%s/%04d", out, n); print "# " FILENAME ":" NR > file; next
  }
  { marked = 0 }
  END { if (inblock) { print "unterminated block at end of file" > "/dev/stderr"; exit 1 } }
' "$markdown"

count=$(find "$scratch/blocks" -type f | wc -l)
if [ "$count" -eq 0 ]; then
  echo "check-readme: $markdown has no block marked <!-- check --> before a \`\`\`sh fence" >&2
  exit 1
fi
if [ "$list" -eq 1 ]; then
  cat "$scratch/blocks"/*
  exit 0
fi

mkdir "$scratch/bin"
ln -s "$cli" "$scratch/bin/sgtllc"
failed=0
for block in "$scratch/blocks"/*; do
  where=$(head -n 1 "$block" | cut -c3-)
  work="$scratch/run/clone"
  rm -rf "$scratch/run"
  mkdir -p "$work"
  for entry in "$repo"/* "$repo"/.ci; do
    [ -e "$entry" ] || continue
    name=$(basename "$entry")
    case $name in build*) continue ;; esac
    ln -s "$entry" "$work/$name"
  done
  if (cd "$work" && PATH="$scratch/bin:$PATH" sh -e "$block") > "$scratch/log" 2>&1; then
    echo "ok   $where"
  else
    echo "FAIL $where"
    sed 's/^/     | /' "$scratch/log"
    failed=$((failed + 1))
  fi
done
echo "check-readme: $count blocks, $failed failed"
[ "$failed" -eq 0 ]

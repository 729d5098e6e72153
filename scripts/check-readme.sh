#!/bin/sh
# Runs the README's runnable shell blocks as written, against a built sgtllc, and fails if any command fails or
# prints other figures than the README shows.
#
#   scripts/check-readme.sh [--list] [--build DIR] [MARKDOWN [SGTLLC]]   (defaults: README.md, build/apps/sgtllc/sgtllc)
#
# A block is runnable when the line just before its ```sh fence is the comment <!-- check -->. Each marked block
# runs on its own with `sh -e` in a fresh scratch folder that holds links to the repository's top-level entries
# (data/, configs/, ...; a README command uses the bundled data only, never anything outside the repository),
# and with `sgtllc` on PATH as the given binary: relative paths work as in a clone, outputs land in the scratch
# folder. Lines starting with # are comments, as in any shell; those after the block's first command are its
# expected output, as the README shows it: the block fails unless its output holds the text of each (after "# ").
# A plain ``` block just after the comment <!-- output of: COMMAND --> is what COMMAND prints: COMMAND runs as a
# marked block does, and its output must hold every line of the block except "..." (elided lines) and lines
# starting with "== " (the headers `make demo` echoes).
# --build DIR also checks the figures of the build tree DIR that the README quotes: the test count "(N tests)"
# against `ctest -N`, and "(A of the B build steps" against `ninja -t commands` for sgtllc_cli and for everything.
# Both depend on the configuration: DIR must be configured as `make test` does (the defaults).
# --list prints the marked blocks (file line and text) instead of running them.
# A file without any marked block fails: that is almost always a lost marker, not a README without commands.
set -eu

list=0
build=
while [ $# -gt 0 ]; do
  case $1 in
    --list) list=1; shift ;;
    --build) [ $# -ge 2 ] || { echo "check-readme: --build needs a build directory" >&2; exit 2; }
             build=$2; shift 2 ;;
    *) break ;;
  esac
done
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
# One file per checked block: blocks/NNNN holds the commands, its first line the README line of the fence;
# expect/NNNN, if any, the lines its output must hold.
mkdir "$scratch/blocks" "$scratch/expect"
awk -v out="$scratch/blocks" -v expect="$scratch/expect" '
  function open_block(kind) {
    n++; file = sprintf("%s/%04d", out, n); want = sprintf("%s/%04d", expect, n)
    print "# " FILENAME ":" NR > file
    inblock = kind; commands = 0
  }
  function close_block() { close(file); if (wanted) close(want); inblock = ""; wanted = 0 }
  function expect_line(text) { print text > want; wanted = 1 }
  /^<!-- check -->[ \t]*$/ { marked = NR; next }
  /^<!-- output of: .* -->[ \t]*$/ {
    output_cmd = $0; sub(/^<!-- output of: /, "", output_cmd); sub(/ -->[ \t]*$/, "", output_cmd)
    output_at = NR; next
  }
  inblock && /^```/ { close_block(); next }
  inblock == "sh" {
    print > file
    if ($0 ~ /^[ \t]*#/) {
      if (commands > 0) { line = $0; sub(/^[ \t]*# ?/, "", line); if (line != "") expect_line(line) }
    } else if ($0 !~ /^[ \t]*$/) {
      commands++
    }
    next
  }
  inblock == "output" {
    if ($0 != "..." && $0 !~ /^== / && $0 !~ /^[ \t]*$/) expect_line($0)
    next
  }
  /^```(sh|bash|shell)[ \t]*$/ && marked == NR - 1 { open_block("sh"); next }
  /^```[ \t]*$/ && output_at == NR - 1 { open_block("output"); print output_cmd > file; next }
  { marked = 0 }
  END { if (inblock != "") { print "unterminated block at end of file" > "/dev/stderr"; exit 1 } }
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
  if ! (cd "$work" && PATH="$scratch/bin:$PATH" sh -e "$block") > "$scratch/log" 2>&1; then
    echo "FAIL $where"
    sed 's/^/     | /' "$scratch/log"
    failed=$((failed + 1))
    continue
  fi
  # The figures the README shows: each expected line somewhere in the output.
  missing=0
  want="$scratch/expect/$(basename "$block")"
  if [ -f "$want" ]; then
    while IFS= read -r line; do
      if ! grep -qF -- "$line" "$scratch/log"; then
        [ "$missing" -gt 0 ] || echo "FAIL $where: the output lacks lines the README shows"
        echo "     - $line"
        missing=$((missing + 1))
      fi
    done < "$want"
  fi
  if [ "$missing" -gt 0 ]; then
    sed 's/^/     | /' "$scratch/log"
    failed=$((failed + 1))
  else
    echo "ok   $where"
  fi
done

# Figures of the build tree: the first number the README gives for each, against the one the tools count now.
if [ -n "$build" ]; then
  figure() {  # figure WHAT README-VALUE ACTUAL
    count=$((count + 1))
    if [ -n "$2" ] && [ "$2" = "$3" ]; then
      echo "ok   $markdown: $1 $2"
    else
      echo "FAIL $markdown: $1: the README says ${2:-nothing}, the build tree gives $3"
      failed=$((failed + 1))
    fi
  }
  [ -f "$build/build.ninja" ] || { echo "check-readme: $build: no build.ninja (a Ninja build tree)" >&2; exit 1; }
  tests=$(ctest --test-dir "$build" -N | sed -n 's/^Total Tests: //p')
  figure "tests (ctest -N)" "$(grep -o 'CTest ([0-9,]* tests)' "$markdown" | head -n 1 | tr -dc 0-9)" "$tests"
  steps=$(grep -o '([0-9,]* of the [0-9,]* build steps' "$markdown" | head -n 1)
  cli_steps=$(ninja -C "$build" -t commands sgtllc_cli | wc -l)
  all_steps=$(ninja -C "$build" -t commands | wc -l)
  figure "build steps of sgtllc_cli" "$(echo "$steps" | sed 's/ of the.*//' | tr -dc 0-9)" "$cli_steps"
  figure "build steps in all" "$(echo "$steps" | sed 's/.* of the//' | tr -dc 0-9)" "$all_steps"
fi
echo "check-readme: $count blocks, $failed failed"
[ "$failed" -eq 0 ]

#!/bin/sh
# Runs the tests of a sanitizer build (README "Reliability checks"; `make test-sanitize`, `make test-tsan`):
#   scripts/sanitize/check.sh asan BUILD_DIR            (the whole suite, through ctest)
#   scripts/sanitize/check.sh tsan BUILD_DIR TEST...    (those test programs, then the threaded commands)
# Every report, also one from the command-line tool that a test runs and whose exit code the test expects to be
# non-zero, goes to BUILD_DIR/sanitizer-logs/; the check fails if that folder is not empty at the end.
set -eu
mode=$1
build=$(cd "$2" && pwd)
shift 2
here=$(cd "$(dirname "$0")" && pwd)
logs=$build/sanitizer-logs
rm -rf "$logs"
mkdir -p "$logs"
# exitcode 86: a report stands out from the tool's own exit codes (1 and 2) in a test's failure message.
common="halt_on_error=1:exitcode=86:log_path=$logs/report"
status=0

case $mode in
  asan)
    export ASAN_OPTIONS="$common:detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1"
    export UBSAN_OPTIONS="$common:print_stacktrace=1"
    export LSAN_OPTIONS="suppressions=$here/lsan.supp:print_suppressions=0"
    (cd "$build" && ctest --output-on-failure -j 2) || status=1
    ;;
  tsan)
    # The project's threads are std::thread (parallelFor), which TSan sees whole; uninstrumented libraries are
    # ignored.
    export TSAN_OPTIONS="$common:ignore_noninstrumented_modules=1:second_deadlock_stack=1"
    "$here/tsan-paths.sh" "$build" "$@" || status=1
    ;;
  *)
    echo "usage: check.sh asan BUILD_DIR | check.sh tsan BUILD_DIR TEST..."
    exit 2
    ;;
esac

reports=$(find "$logs" -type f | wc -l)
if [ "$reports" -gt 0 ]; then
  for f in "$logs"/*; do
    echo "== $f"
    cat "$f"
  done
  echo "$mode: $reports sanitizer report(s) (above; also in $logs)"
  exit 1
fi
[ $status -eq 0 ] && echo "$mode: no sanitizer report"
exit $status

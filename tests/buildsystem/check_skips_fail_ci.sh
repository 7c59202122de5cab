#!/usr/bin/env bash
# A skipped test fails CI: ctest itself passes a run with a skipped test (exit 0), so CI's
# script reads ctest's summary (scripts/fresh-machine.sh --tests-not-run, applied to every
# command's log). Here: a two-test project, one passing and one skipping the way the suite's
# guards and corpus scripts skip (SKIP_RETURN_CODE, GoogleTest's "[  SKIPPED ]"); its ctest
# exits 0, and the check fails the log naming the skipped tests. Without the skips it passes.
# Usage: check_skips_fail_ci.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/project"
cat >"$work/project/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.16)
project(skips NONE)
enable_testing()
add_test(NAME Passes COMMAND true)
add_test(NAME SkipsByReturnCode COMMAND sh -c "exit 77")
set_tests_properties(SkipsByReturnCode PROPERTIES SKIP_RETURN_CODE 77)
add_test(NAME SkipsLikeGoogleTest COMMAND sh -c "echo '[  SKIPPED ] Suite.Name'")
set_tests_properties(SkipsLikeGoogleTest PROPERTIES SKIP_REGULAR_EXPRESSION "\\[  SKIPPED \\]")
CMAKE
cmake -S "$work/project" -B "$work/build" >/dev/null
ctest --test-dir "$work/build" >"$work/ctest.log" 2>&1 || { cat "$work/ctest.log"; echo "ctest failed: expected it to pass with skips" >&2; exit 1; }
if not_run=$("$source_dir/scripts/fresh-machine.sh" --tests-not-run "$work/ctest.log"); then
  cat "$work/ctest.log"
  echo "the check passed a ctest log with skipped tests" >&2
  exit 1
fi
for name in SkipsByReturnCode SkipsLikeGoogleTest; do
  grep -q "$name" <<<"$not_run" || { echo "the check did not name $name: $not_run" >&2; exit 1; }
done
echo "skipped tests named: $(echo $not_run)"

# The same project with the two skipping tests left out of the run: nothing to report.
ctest --test-dir "$work/build" -E Skips >"$work/ctest.log" 2>&1
"$source_dir/scripts/fresh-machine.sh" --tests-not-run "$work/ctest.log" >/dev/null || { cat "$work/ctest.log"; echo "the check failed a log without skips" >&2; exit 1; }
echo "a run without skips passes"

#!/usr/bin/env bash
# Builds collidescope with sanitizers and runs the whole test suite under them
# (docs/sanitizers.md). Usage: scripts/sanitize.sh address|thread [CTEST_ARGS...]
#   address: AddressSanitizer + UndefinedBehaviorSanitizer, in build-asan/
#   thread:  ThreadSanitizer (with the TBB bridge, tests/sanitize/), in build-tsan/
# Incremental: an existing build directory is reused. The options and suppressions are built
# into the executables, so `ctest --test-dir build-asan` alone also works after a build.
# Extra arguments go to ctest (e.g. -R replay, -L bvh; README command (b) gives -LE corpus).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

kind=${1:-}
# RelWithDebInfo: optimised (the tests run the exact narrow phase over many pairs) with line
# numbers in the reports: -g1, line tables only, which is all a report's stack needs and
# compiles faster than -g (the CI machine has 2 cores and 90 minutes for both builds and both
# suites). ThreadSanitizer at -O1: its runtime dominates the run time anyway, and -O1 compiles
# faster.
case "$kind" in
  address) build=build-asan; flags="-O2 -g1 -DNDEBUG" ;;
  thread) build=build-tsan; flags="-O1 -g1 -DNDEBUG" ;;
  *)
    echo "usage: scripts/sanitize.sh address|thread [CTEST_ARGS...]" >&2
    exit 2
    ;;
esac
shift

# No benchmarks: they are not tests.
cmake -S . -B "$build" -DCOLLIDESCOPE_SANITIZE="$kind" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" -DCOLLIDESCOPE_BENCH=OFF
cmake --build "$build" -j2
ctest --test-dir "$build" --output-on-failure -j2 "$@"

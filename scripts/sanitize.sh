#!/usr/bin/env bash
# Builds collidescope with sanitizers and runs the whole test suite under them
# (docs/how-to/sanitizers.md). Usage: scripts/sanitize.sh address|thread [CTEST_ARGS...]
#   address: AddressSanitizer + UndefinedBehaviorSanitizer, in build-asan/
#   thread:  ThreadSanitizer (with the TBB bridge, tests/sanitize/), in build-tsan/
# Incremental: an existing build directory is reused. The options and suppressions are built
# into the executables, so `ctest --test-dir build-asan` alone also works after a build.
# Extra arguments go to ctest (e.g. -R replay, -L bvh; README command (b) gives -LE corpus).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

kind=${1:-}
# RelWithDebInfo with line numbers in the reports: -g1, line tables only, which is all a
# report's stack needs and compiles faster than -g (CI has 2 cores and 45 minutes for both
# builds and both suites). -Og, which compiles under ASan and UBSan's checks in about half the
# time of -O1 (tests/app/test_named_options.cpp: 26.6 s at -O1, 14.0 s at -Og; -O0 is no
# faster and runs slower); the address build compiles the engine and the tests' references at
# -O1 all the same (the tests run the exact narrow phase over many pairs; -O2 took 1.75 times
# the engine's compile time under the sanitizers, for no measurable gain in the suite's time;
# tests/sanitize/sanitize.cmake). ThreadSanitizer at -O1 everywhere: its runtime dominates.
case "$kind" in
  address) build=build-asan; flags="-Og -g1 -DNDEBUG"; hot=-O1 ;;
  thread) build=build-tsan; flags="-O1 -g1 -DNDEBUG"; hot="" ;;
  *)
    echo "usage: scripts/sanitize.sh address|thread [CTEST_ARGS...]" >&2
    exit 2
    ;;
esac
shift

# Every sanitizer exits 86 on a finding, never 1 (which the app uses for "collisions found"):
# built into the executables (tests/sanitize/*_defaults.cpp) and said again here, after any
# options from the caller's environment, so that no ASAN_OPTIONS=exitcode=1 can undo it.
for variable in ASAN_OPTIONS UBSAN_OPTIONS LSAN_OPTIONS TSAN_OPTIONS; do
  export "$variable=${!variable:+${!variable}:}exitcode=86"
done

# Each phase's time, for CI's phase table (scripts/fresh-machine.sh reads these lines).
phase() {
  local name=$1 started=$SECONDS
  shift
  "$@"
  echo "sanitize: phase $name took $((SECONDS - started)) s"
}

# No benchmarks: they are not tests.
phase "$build configure" cmake -S . -B "$build" -DCOLLIDESCOPE_SANITIZE="$kind" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" -DCOLLIDESCOPE_SANITIZE_HOT_OPTIMIZATION="$hot" -DCOLLIDESCOPE_BENCH=OFF
phase "$build build" cmake --build "$build" -j2
phase "$build ctest" ctest --test-dir "$build" --output-on-failure -j2 "$@"

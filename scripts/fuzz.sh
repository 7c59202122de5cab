#!/usr/bin/env bash
# Builds and runs the libFuzzer targets of the input readers (docs/how-to/fuzzing.md). Not part of
# CI: a run is measured in tens of minutes. Needs clang-14 and its runtime (Debian packages,
# installed here when missing, like setup.sh does; run setup.sh first for the rest).
#
#   scripts/fuzz.sh build                      configure build-fuzz/ with clang and build
#   scripts/fuzz.sh run TARGET|all [SECONDS]   fuzz (default 1800 s each; all = one after another)
#   scripts/fuzz.sh merge TARGET|all           minimise the run's corpus into tests/fuzz/corpus/
#
# Targets: ply, obj, scene, recording, cache. A run starts from tests/fuzz/corpus/TARGET (copied into
# build-fuzz/corpus/TARGET, which keeps growing across runs), writes crashing inputs to
# build-fuzz/findings/TARGET/ and its log to build-fuzz/logs/TARGET.log. Environment:
# FUZZ_BUILD (build directory, default build-fuzz), FUZZ_JOBS (build jobs, default 2),
# FUZZ_NICE (niceness of the run, default 10).
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${FUZZ_BUILD:-$ROOT/build-fuzz}
TARGETS=(ply obj scene recording cache)
PACKAGES=(clang-14 libclang-rt-14-dev)

log() { echo "fuzz: $*"; }

# shellcheck source=apt_packages.sh
source "$ROOT/scripts/apt_packages.sh"

build() {
  install_packages "${PACKAGES[@]}"
  # -O1 with assertions on: an assertion that fires is a finding too.
  cmake -S "$ROOT" -B "$BUILD" -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
    -DCMAKE_BUILD_TYPE=FuzzDebug -DCMAKE_CXX_FLAGS_FUZZDEBUG="-O1 -g" -DCMAKE_C_FLAGS_FUZZDEBUG="-O1 -g" \
    -DCOLLIDESCOPE_FUZZ=ON -DCOLLIDESCOPE_TESTS=OFF -DCOLLIDESCOPE_BENCH=OFF >/dev/null
  cmake --build "$BUILD" -j"${FUZZ_JOBS:-2}" --target "${TARGETS[@]/#/fuzz_}"
}

# Copies the committed inputs into a run's corpus, gunzipping the .gz ones (recordings are
# committed gzipped: 140 KiB of mostly unallocated chunk space packs into 9 KiB).
unpack_corpus() {
  local from=$1 to=$2 file name
  for file in "$from"/*; do
    [ -f "$file" ] || continue
    name=$(basename "$file")
    if [ "${name%.gz}" != "$name" ]; then
      [ -e "$to/${name%.gz}" ] || gunzip -c "$file" >"$to/${name%.gz}"
    else
      [ -e "$to/$name" ] || cp "$file" "$to/$name"
    fi
  done
}

# One target for SECONDS: leak detection on (ASan's default), 10 s per input counts as a hang,
# 2 GiB as running out of memory.
run_one() {
  local target=$1 seconds=$2
  local corpus=$BUILD/corpus/$target findings=$BUILD/findings/$target
  mkdir -p "$corpus" "$findings" "$BUILD/logs"
  unpack_corpus "$ROOT/tests/fuzz/corpus/$target" "$corpus"
  log "fuzzing $target for $seconds s (log: $BUILD/logs/$target.log)"
  # fuzz/lsan.supp names the one leak inside libhdf5 we cannot fix; matching it needs full
  # stacks through the uninstrumented library, so the recording target unwinds slowly on malloc.
  local unwind=1 status=0
  [ "$target" = recording ] && unwind=0
  ASAN_OPTIONS=${ASAN_OPTIONS:-fast_unwind_on_malloc=$unwind} \
  LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$ROOT/fuzz/lsan.supp:print_suppressions=0} \
  nice -n "${FUZZ_NICE:-10}" "$BUILD/fuzz/fuzz_$target" "$corpus" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -detect_leaks=1 -print_final_stats=1 \
    -artifact_prefix="$findings/" >"$BUILD/logs/$target.log" 2>&1 || status=$?
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb|^(==[0-9]+==)?ERROR|SUMMARY|Test unit written" \
    "$BUILD/logs/$target.log" | sed "s/^/fuzz: $target: /" || true
  return "$status"
}

# Keeps the inputs of the run's corpus that add coverage, replacing the committed corpus.
# -use_counters=0: an input stays for a new edge, not for a new hit count of a known one, so
# the committed corpus keeps every edge the runs reached in a few hundred small files (the
# run's own corpus in build-fuzz/ keeps everything).
merge_one() {
  local target=$1
  local committed=$ROOT/tests/fuzz/corpus/$target fresh unpacked
  fresh=$(mktemp -d)
  unpacked=$(mktemp -d)
  unpack_corpus "$committed" "$unpacked"
  ASAN_OPTIONS=fast_unwind_on_malloc=0 LSAN_OPTIONS=suppressions=$ROOT/fuzz/lsan.supp:print_suppressions=0 \
  "$BUILD/fuzz/fuzz_$target" -merge=1 -use_counters=0 "$fresh" "$unpacked" "$BUILD/corpus/$target" \
    >"$BUILD/logs/$target.merge.log" 2>&1
  rm -rf "$committed"
  mkdir -p "$committed"
  cp "$fresh"/* "$committed"/
  if [ "$target" = recording ]; then gzip -9n "$committed"/*; fi
  rm -rf "$fresh" "$unpacked"
  log "$target: $(ls "$committed" | wc -l) inputs, $(cat "$committed"/* | wc -c) bytes in tests/fuzz/corpus/$target"
}

targets_of() {
  if [ "$1" = all ]; then echo "${TARGETS[@]}"; else echo "$1"; fi
}

main() {
  local command=${1:-}
  case "$command" in
    build) build ;;
    run)
      [ $# -ge 2 ] || { echo "usage: $0 run TARGET|all [SECONDS]" >&2; exit 2; }
      build
      local target status=0
      for target in $(targets_of "$2"); do run_one "$target" "${3:-1800}" || status=1; done
      return "$status"
      ;;
    merge)
      [ $# -ge 2 ] || { echo "usage: $0 merge TARGET|all" >&2; exit 2; }
      local target
      for target in $(targets_of "$2"); do merge_one "$target"; done
      ;;
    *) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
  esac
}

main "$@"

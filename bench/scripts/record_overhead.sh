#!/usr/bin/env bash
# What recording costs: the same scene run by `check` and by `record` (no depth buffers),
# interleaved, RUNS times each; prints the median wall time of each, their ratio, and the
# file size per frame. Run from the repository root after building (BIN = the binary).
#
#   [RECORD_ARGS="--compression 0"] bench/scripts/record_overhead.sh [SCENE] [RUNS] [THREADS] [METHOD]
#   (default: demo 7 0 brute)
set -euo pipefail
SCENE=${1:-demo}
RUNS=${2:-7}
THREADS=${3:-0}
METHOD=${4:-brute}
BIN=${BIN:-build/app/collidescope}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

now() { date +%s.%N; }
median() { sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }

check_times=()
record_times=()
"$BIN" check --scene "$SCENE" --method "$METHOD" --threads "$THREADS" -q --exit-zero 2>/dev/null  # warm-up
for _ in $(seq "$RUNS"); do
  t0=$(now); "$BIN" check --scene "$SCENE" --method "$METHOD" --threads "$THREADS" -q --exit-zero 2>/dev/null; t1=$(now)
  "$BIN" record --scene "$SCENE" --method "$METHOD" --threads "$THREADS" -q -o "$OUT/run.h5" ${RECORD_ARGS:-} 2>/dev/null; t2=$(now)
  check_times+=("$(echo "$t1 - $t0" | bc -l)")
  record_times+=("$(echo "$t2 - $t1" | bc -l)")
done
check_median=$(printf '%s\n' "${check_times[@]}" | median)
record_median=$(printf '%s\n' "${record_times[@]}" | median)
frames=$(/usr/bin/python3 -c "import h5py,sys; print(len(h5py.File(sys.argv[1],'r')['frames/index']))" "$OUT/run.h5")
bytes=$(stat -c %s "$OUT/run.h5")
printf 'scene %s, method %s, threads %s (0 = all), record args [%s], %s runs each, %s\n' "$SCENE" "$METHOD" "$THREADS" "${RECORD_ARGS:-}" "$RUNS" "$(date -u +%FT%TZ)"
printf 'check  median %.3f s\nrecord median %.3f s\nratio record/check %.3f\n' "$check_median" "$record_median" \
  "$(echo "$record_median / $check_median" | bc -l)"
printf 'file %d bytes, %d frames, %.0f bytes per frame\n' "$bytes" "$frames" "$(echo "$bytes / $frames" | bc -l)"

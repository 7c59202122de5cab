#!/usr/bin/env bash
# Encoding `replay --video out.mp4` against writing the PNG frames of the same replay, at
# 1280x720 (issue 28, item 9): records data set C:large (260,100 triangles) with the AABB
# method once, then replays it RUNS times each way with THREADS render threads: PNGs only
# (-o DIR), the MP4 only (--video), the GIF only, and PNGs plus MP4, printing each run's wall
# and CPU seconds, the outputs' sizes, the thread seconds of each step and the machine's load. Usage:
#   bench/scripts/video_bench.sh [BUILD_DIR] [FRAMES] [RUNS] [THREADS]
set -euo pipefail
build=${1:-build}
frames=${2:-40}
runs=${3:-3}
threads=${4:-2}
bin="$build/app/collidescope"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" record --scene C:large --method aabb --frames "0:$frames" -o "$work/run.h5" -q
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $frames frames at 1280x720, $threads render threads"
# One replay: wall seconds and CPU seconds (user + system, every thread of the process: the
# render threads, x264's own threads), the outputs' sizes and the rate line.
one() {
  local name=$1
  shift
  rm -rf "$work/frames" "$work/clip.mp4" "$work/clip.gif"
  local timing rate size=""
  timing=$( { TIMEFORMAT='%R %U %S'; time "$bin" replay "$work/run.h5" --size 1280x720 --threads "$threads" "$@" \
      2>"$work/err" >/dev/null; } 2>&1 )
  rate=$(grep '^rendered' "$work/err" | sed 's/.*thread seconds: /thread seconds: /')
  [ -f "$work/clip.mp4" ] && size=" mp4 $(stat -c %s "$work/clip.mp4") B"
  [ -f "$work/clip.gif" ] && size=" gif $(stat -c %s "$work/clip.gif") B"
  [ -d "$work/frames" ] && size="$size pngs $(du -sb "$work/frames" | cut -f1) B"
  read -r real user sys <<<"$timing"
  printf '%-8s wall %6.2f s, cpu %6.2f s, load %s;%s; %s\n' "$name" "$real" "$(awk "BEGIN { print $user + $sys }")" \
    "$(cut -d' ' -f1 /proc/loadavg)" "$size" "$rate"
}
for run in $(seq "$runs"); do
  echo "run $run"
  one png -o "$work/frames"
  one mp4 --video "$work/clip.mp4"
  one gif --video "$work/clip.gif"
  one png+mp4 -o "$work/frames" --video "$work/clip.mp4"
done

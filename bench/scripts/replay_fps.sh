#!/usr/bin/env bash
# Frames per second of `collidescope replay` at 1280x720 on a ~200k-triangle recording (issue 8):
# records data set C:large (260,100 triangles) with the AABB method once, then replays it with
# 1 and 2 render threads, RUNS times each, and prints each run's rate line, the machine's load
# and its cores. Usage: bench/scripts/replay_fps.sh [BUILD_DIR] [FRAMES] [RUNS]
set -euo pipefail
build=${1:-build}
frames=${2:-40}
runs=${3:-3}
bin="$build/app/collidescope"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" record --scene C:large --method aabb --frames "0:$frames" -o "$work/C_large.h5" -q
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
for run in $(seq "$runs"); do
  for threads in 1 2; do
    echo "run $run, load $(cut -d' ' -f1-3 /proc/loadavg): $("$bin" replay "$work/C_large.h5" -o "$work/frames" --threads "$threads" 2>&1 >/dev/null | grep '^rendered')"
  done
done

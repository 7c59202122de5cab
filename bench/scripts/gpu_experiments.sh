#!/usr/bin/env bash
# The thesis's Mode 2 experiments (section 5.1) on this machine: for data sets A, B and C, the
# GPU cull with each mechanism on and off, every fixed view configuration, fixed triangles per
# query, the naive baseline, and queries against flags. Prints one table row per run: total
# milliseconds over the animation (the whole frame, and the cull alone) and the triangles left
# in the PCS, summed over frames. Every run's pairs are checked against brute force.
#
#   bench/scripts/gpu_experiments.sh [PRESET] [BINARY]      (defaults: small, build/app/collidescope)
set -euo pipefail
preset=${1:-small}
binary=${2:-build/app/collidescope}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

run() {  # scene label args...
  local scene=$1 label=$2
  shift 2
  "$binary" check --scene "$scene:$preset" --exit-zero -q --threads 2 --pairs "$work/pairs.tsv" \
    --stats "$work/stats.jsonl" "$@" 2>/dev/null
  if ! cmp -s "$work/pairs.tsv" "$work/brute_$scene.tsv"; then
    echo "MISMATCH: $scene $label" >&2
    exit 1
  fi
  /usr/bin/python3 - "$scene" "$label" "$work/stats.jsonl" <<'PY'
import json, sys
scene, label, path = sys.argv[1:]
frames = [json.loads(line) for line in open(path)]
total = sum(f["ms"]["total"] for f in frames)
cull = sum(f["ms"]["cull"] for f in frames)
pcs = sum(f.get("gpu", {}).get("pcs_triangles", [0, 0])[1] for f in frames)
queries = sum(f.get("gpu", {}).get("queries", 0) for f in frames)
print(f"| {scene} | {label} | {total:.0f} | {cull:.0f} | {pcs} | {queries} |")
PY
}

echo "| scene | configuration | total ms | cull ms | PCS triangles left | queries |"
echo "| --- | --- | --- | --- | --- | --- |"
for scene in A B C; do
  "$binary" check --scene "$scene:$preset" --exit-zero -q --pairs "$work/brute_$scene.tsv" 2>/dev/null
  run "$scene" "aabb (reference)" --method aabb
  run "$scene" "gpu: all three mechanisms" --method gpu
  run "$scene" "gpu-naive" --method gpu-naive
  run "$scene" "sort off" --method gpu --gpu-no-sort
  for views in xyz xzy yxz yzx zxy zyx; do
    run "$scene" "fixed views $views" --method gpu --gpu-fixed-views --gpu-views "$views"
  done
  for p in 1 2 3 4 8 16; do
    run "$scene" "fixed P = $p" --method gpu --gpu-fixed-p --triangles-per-query "$p"
  done
  run "$scene" "flags (query-free)" --method gpu --gpu-cull flags
  run "$scene" "queries, P = 1, fixed views zxy" --method gpu --gpu-fixed-p --triangles-per-query 1 --gpu-fixed-views
  run "$scene" "flags, fixed views zxy" --method gpu --gpu-cull flags --gpu-fixed-views
done

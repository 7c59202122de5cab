#!/usr/bin/env bash
# bench/scripts/harder_scenes.py at its small size, as a user runs it: every scene it writes loads
# through `collidescope check`, and `aabb` (at 1 and 2 threads) and `gpu` return exactly
# `brute`'s pairs on every frame. rods and pile collide somewhere; wrinkled is near contact
# without contact (folds close to each other, no pair touching): no pair on any frame, and on
# every frame `aabb` hands the exact test non-adjacent candidate pairs, so it is not empty by
# being far apart.
# Usage: harder_scenes_exact.sh COLLIDESCOPE SOURCE_DIR
set -euo pipefail
cli=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$source_dir/bench/scripts/harder_scenes.py" "$work" --size small --frames 3
for scene in rods pile wrinkled; do
  "$cli" check "$work/$scene/scene.json" --method brute --pairs "$work/$scene.brute.tsv" --exit-zero -q
  for run in "aabb 1" "aabb 2" "gpu 2"; do
    set -- $run
    "$cli" check "$work/$scene/scene.json" --method "$1" --threads "$2" --pairs "$work/$scene.$1.tsv" --exit-zero -q
    if ! cmp -s "$work/$scene.brute.tsv" "$work/$scene.$1.tsv"; then
      echo "$scene: $1 at $2 threads differs from brute" >&2
      diff "$work/$scene.brute.tsv" "$work/$scene.$1.tsv" | head -5 >&2
      exit 1
    fi
  done
  echo "$scene: $(wc -l < "$work/$scene.brute.tsv") colliding pairs, aabb and gpu equal brute"
  if [ "$scene" != wrinkled ] && [ ! -s "$work/$scene.brute.tsv" ]; then
    echo "$scene: no colliding pair (the scene should have contact)" >&2
    exit 1
  fi
done
if [ -s "$work/wrinkled.brute.tsv" ]; then
  echo "wrinkled: $(wc -l < "$work/wrinkled.brute.tsv") colliding pairs (the scene should have none)" >&2
  exit 1
fi
"$cli" check "$work/wrinkled/scene.json" --method aabb --stats "$work/wrinkled.stats.jsonl" --exit-zero -q
/usr/bin/python3 - "$work/wrinkled.stats.jsonl" <<'EOF'
import json, sys
frames = [json.loads(line) for line in open(sys.argv[1])]
candidates = [frame["counts"]["candidate_pairs"] for frame in frames]
print("wrinkled: exact tests on candidate pairs per frame:", candidates)
if len(frames) != 3 or min(candidates) == 0:
    sys.exit("wrinkled: a frame without candidate pairs (the folds should come near each other)")
EOF

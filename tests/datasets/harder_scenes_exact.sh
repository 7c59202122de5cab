#!/usr/bin/env bash
# scripts/harder_scenes.py at its small size, as a user runs it: every scene it writes loads
# through `collidescope check`, collides somewhere (rods and pile), and `aabb` (at 1 and 2
# threads) and `gpu` return exactly `brute`'s pairs on every frame.
# Usage: harder_scenes_exact.sh COLLIDESCOPE SOURCE_DIR
set -euo pipefail
cli=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$source_dir/scripts/harder_scenes.py" "$work" --size small --frames 3
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

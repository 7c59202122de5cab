#!/bin/bash
# The runs of 2026-11-24-degenerate-predicates.md. usage: SCRIPT OLD_BINARY NEW_BINARY WORKDIR
# 1. counts: new binary on the cloth family (large) and B, C; 2. A/B narrow-phase timing on
# exported frames, old and new binaries alternated, 3 rounds; pairs compared.
set -u
OLD=$1; NEW=$2; W=$3; mkdir -p "$W"; cd "$W"
for s in cloth-rest:large:0:2 cloth-drape:large:8:10 cloth-crumple:large:8:10 cloth-slide:large:0:2 B:default:150:152 C:default:100:102; do
  scene=${s%:*:*}; r=${s#*:*:}
  "$NEW" check --scene "$scene" --method aabb --threads 2 --frames "${r%:*}:${r#*:}" --stats "counts.${scene//:/_}.jsonl" >/dev/null 2>&1
done
"$NEW" export cloth-rest:large --frames 0:1 -o rest0 -q
"$NEW" export cloth-slide:large --frames 0:1 -o slide0 -q
"$NEW" export cloth-drape:large --frames 9:10 -o drape9 -q
"$NEW" export cloth-crumple:large --frames 9:10 -o crumple9 -q
for round in 1 2 3; do
  for d in rest0 slide0 drape9 crumple9; do
    for tag in old new; do
      B=$OLD; [ $tag = new ] && B=$NEW
      "$B" check $d/scene.json --self --method aabb --threads 2 --stats ab.$tag.$d.$round.jsonl --pairs ab.$tag.$d.$round.pairs >/dev/null 2>&1
    done
  done
done
for d in rest0 slide0 drape9 crumple9; do cmp ab.old.$d.1.pairs ab.new.$d.1.pairs && echo "$d: same pairs"; done

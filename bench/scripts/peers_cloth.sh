#!/usr/bin/env bash
# Issue 23's peer comparison (records/2026-11-25-cloth-peers.md): `aabb` at 1 and 2
# threads against the peer users would assemble (Embree 3 refit + CGAL exact predicates with
# the self rule, bench/peers/bench_embree_cgal_peers) and FCL, on the cloth family at the large
# preset (self-collision on) and the thesis data sets at the default preset (objects only, as
# bench_bvh_peers, and again with self-collision on); then `check --stats` on every frame of
# the cloth scenes for exact_fallbacks per exact test. Five frames per scene, spread evenly from
# the first to the last, the same for every method, after one untimed warm-up frame (the first
# of them). FCL is timed on the first of them only (it takes seconds per frame). Data set E
# needs the Stanford dragon: set COLLIDESCOPE_DATA when it is not in the repository's data/.
# Usage: bench/scripts/peers_cloth.sh BUILD_DIR OUT_DIR   (BUILD_DIR built with COLLIDESCOPE_BENCH=ON
#        and the targets bench_embree_cgal_peers, collidescope). Writes OUT_DIR/peers.jsonl,
#        OUT_DIR/peers-low.jsonl, OUT_DIR/stats-*.jsonl, OUT_DIR/load.txt, OUT_DIR/machine.txt,
#        and the tables on stdout.
set -euo pipefail
build=$(realpath "$1")
out=$2
bench=$build/bench/bench_embree_cgal_peers
cli=$build/app/collidescope
mkdir -p "$out"
here=$(dirname "$(realpath "${BASH_SOURCE[0]}")")

{ date -u; uptime; echo "cores: $(nproc)"; free -g | head -2; git -C "$here" rev-parse HEAD; } > "$out/machine.txt"
: > "$out/peers.jsonl"
: > "$out/peers-low.jsonl"
: > "$out/load.txt"

note() { echo "$(date -u +%T) load $(cut -d' ' -f1-3 /proc/loadavg): $*" | tee -a "$out/load.txt" >&2; }
peer() {  # peer ARGS...: one bench run, its JSON line appended; a difference (exit 2) is kept
  note "bench_embree_cgal_peers $*"
  local rc=0
  "$bench" "$@" >> "$out/peers.jsonl" || rc=$?
  [ "$rc" -eq 0 ] || note "exit $rc: $*"
}

note "the peer's exact test against the engine's on random degenerate pairs"
"$bench" --check-rule 1000000 | tee "$out/check_rule.json" >&2

for scene in cloth-rest cloth-drape cloth-crumple cloth-slide; do
  peer --scene "$scene:large" --self on --fcl-frames 1
done
for scene in A B C D E1 E2 E3 E4; do peer --scene "$scene" --self off --fcl-frames 1; done
for scene in A B C D E1 E2 E3 E4; do peer --scene "$scene" --self on --no-fcl; done
# The peer with Embree building its trees again every frame (RTC_BUILD_QUALITY_LOW) instead of
# refitting them (DESIGN.md: compare both modes), cloth scenes, against aabb at 2 threads.
for scene in cloth-rest cloth-drape cloth-crumple cloth-slide; do
  note "bench_embree_cgal_peers --scene $scene:large --embree-build low"
  "$bench" --scene "$scene:large" --self on --threads 2 --no-fcl --no-split --embree-build low \
    >> "$out/peers-low.jsonl" || note "exit $?"
done

for scene in cloth-rest cloth-drape cloth-crumple cloth-slide; do
  note "collidescope check --scene $scene:large --method aabb --self --threads 2 --stats"
  "$cli" check --scene "$scene:large" --method aabb --self --threads 2 -q \
    --stats "$out/stats-$scene.jsonl" > /dev/null || [ $? -eq 1 ]
done
note "done"

/usr/bin/python3 "$here/peers_cloth_table.py" "$out"

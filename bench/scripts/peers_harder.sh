#!/usr/bin/env bash
# The Embree + CGAL peer against `aabb` on the scenes of bench/scripts/harder_scenes.py (capped
# tubes, a sphere pile, an irregular overhanging cloth; self-collision on), as on the built-in
# cloth family (bench/scripts/peers_cloth.sh): frames 1 to 5 of each, after an untimed warm-up
# frame, `aabb` at 1 and 2 threads, ratios from the same process, pairs compared.
# Usage: bench/scripts/peers_harder.sh BUILD_DIR OUT_DIR   (BUILD_DIR with bench_embree_cgal_peers)
#        Writes OUT_DIR/scenes/ (about 65 MB), OUT_DIR/peers.jsonl, OUT_DIR/machine.txt and the
#        table on stdout.
set -euo pipefail
build=$(realpath "$1")
out=$2
here=$(dirname "$(realpath "${BASH_SOURCE[0]}")")
mkdir -p "$out"
{ date -u; uptime; echo "cores: $(nproc)"; git -C "$here" rev-parse HEAD; } > "$out/machine.txt"
[ -f "$out/scenes/wrinkled/scene.json" ] || /usr/bin/python3 "$here/harder_scenes.py" "$out/scenes"
: > "$out/peers.jsonl"
for scene in rods pile wrinkled; do
  echo "$(date -u +%T) load $(cut -d' ' -f1-3 /proc/loadavg): $scene" >&2
  rc=0
  "$build/bench/bench_embree_cgal_peers" "$out/scenes/$scene/scene.json" --self scene --no-fcl \
    --threads 1,2 --frames 1,2,3,4,5 >> "$out/peers.jsonl" || rc=$?
  [ "$rc" -eq 0 ] || echo "$scene: exit $rc (pairs differ?)" >&2
done
/usr/bin/python3 - "$out/peers.jsonl" <<'PY'
import json, sys
print("| scene | triangles | aabb 1 thread ms | aabb 2 threads ms | peer ms | peer / aabb (1, 2 threads) | candidates (aabb / Embree) | pairs equal |")
print("| --- | --- | --- | --- | --- | --- | --- | --- |")
for line in open(sys.argv[1]):
    d = json.loads(line)
    one, two = d["aabb"]
    p = d["peer"]
    print(f"| {d['scene']} | {d['triangles']:,} | {one['ms']:.1f} | {two['ms']:.1f} | {p['ms']:.1f} | "
          f"{p['ms'] / one['ms']:.2f}x, {p['ms'] / two['ms']:.2f}x | {two['candidates']:,.0f} / {p['embree_candidates']:,.0f} | "
          f"{'yes' if p['extra'] + p['missed'] == 0 else 'NO'} |")
PY

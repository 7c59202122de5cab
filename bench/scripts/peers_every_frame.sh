#!/usr/bin/env bash
# Issue 23's comparison on every frame of each animation, in order (what `collidescope check`
# runs), beside bench/scripts/peers_cloth.sh's five frames spread over it: the cloth family at the
# large preset (self-collision on) and the thesis data sets between objects, `aabb` at 1 and
# 2 threads against the Embree 3 refit + CGAL peer, no FCL, after one untimed warm-up frame.
# Spread frames jump 25-50 frames between timed frames, so there every object's first
# contact builds its tree inside a timed frame and most trees are rebuilt; here those costs
# fall where they fall in a real run.
# Usage: bench/scripts/peers_every_frame.sh BUILD_DIR OUT_DIR (as peers_cloth.sh). Writes
#        OUT_DIR/every-frame.jsonl, OUT_DIR/machine.txt and the table on stdout.
set -euo pipefail
build=$(realpath "$1")
out=$2
bench=$build/bench/bench_embree_cgal_peers
mkdir -p "$out"
here=$(dirname "$(realpath "${BASH_SOURCE[0]}")")
{ date -u; uptime; echo "cores: $(nproc)"; free -g | head -2; git -C "$here" rev-parse HEAD; } > "$out/machine.txt"
: > "$out/every-frame.jsonl"
run() {
  echo "$(date -u +%T) load $(cut -d' ' -f1-3 /proc/loadavg): bench_embree_cgal_peers $*" >&2
  local rc=0
  "$bench" "$@" --frames all --no-fcl --no-split >> "$out/every-frame.jsonl" || rc=$?
  [ "$rc" -eq 0 ] || echo "exit $rc: $*" >&2
}
for scene in cloth-rest cloth-drape cloth-crumple cloth-slide; do run --scene "$scene:large" --self on; done
for scene in A B C D E1 E2 E3 E4; do run --scene "$scene" --self off; done
/usr/bin/python3 - "$out/every-frame.jsonl" <<'PY'
import json, math, sys
runs = [json.loads(line) for line in open(sys.argv[1]) if line.strip()]
print("| scene | self | frames | aabb 1 thr ms | aabb 2 thr ms | peer ms | peer / aabb 1 thr | peer / aabb 2 thr | peer differs |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
ratios = []
for r in runs:
    a = {x["threads"]: x for x in r["aabb"]}
    p = r["peer"]
    ratios.append(p["ms"] / a[2]["ms"])
    print(f'| {r["scene"]} | {"on" if r["self"] else "off"} | {len(r["frames"])} | {a[1]["ms"]:,.2f} | {a[2]["ms"]:,.2f} '
          f'| {p["ms"]:,.2f} | {p["ms"] / a[1]["ms"]:.2f}x | {ratios[-1]:.2f}x | {p["extra"]}/{p["missed"]} |')
print()
print(f"Geometric mean of peer / aabb at 2 threads over these {len(ratios)} runs: "
      f"{math.exp(sum(map(math.log, ratios)) / len(ratios)):.2f}x; lowest {min(ratios):.2f}x")
PY

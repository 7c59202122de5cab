"""The table of bench/scripts/peers_cloth.sh from its OUT_DIR: per run, ms per frame of `aabb` (1 and
2 threads) and of the Embree + CGAL peer (refit / collide / narrow), candidate counts, FCL,
the ratios peer / aabb, differences; then issue 23's targets. Usage: peers_cloth_table.py OUT_DIR"""
import glob
import json
import math
import os
import sys


def load(out, name="peers.jsonl"):
    path = os.path.join(out, name)
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def fallbacks(out):
    rows = []
    for path in sorted(glob.glob(os.path.join(out, "stats-*.jsonl"))):
        scene = os.path.basename(path)[len("stats-"):-len(".jsonl")]
        frames = [json.loads(line) for line in open(path) if line.strip()]
        tests = sum(f["counts"]["exact_tests"] for f in frames)
        falls = sum(f["counts"]["exact_fallbacks"] for f in frames)
        worst = max(f["counts"]["exact_fallbacks"] / max(f["counts"]["exact_tests"], 1) for f in frames)
        ms = {k: sum(f["ms"][k] for f in frames) / len(frames) for k in ("refit", "rebuild", "traversal", "narrow", "total")}
        rows.append((scene, len(frames), tests, falls, worst, ms))
    return rows


def geomean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


# Each thesis data set's own self-collision setting, as the data sets define it (Scene::
# self_collision in engine/src/datasets; README's table): B, the waving cloths, is the one with
# self-collision on.
DEFAULT_SELF_ON = {"B"}


def main(out):
    runs = load(out)
    print("| scene | self | triangles | frames | aabb 1 thr ms | aabb 2 thr ms | peer ms (refit / collide / narrow) "
          "| Embree candidates | aabb candidates | colliding | FCL ms (pairs; extra/missed) | peer / aabb 1 thr "
          "| peer / aabb 2 thr | peer differs (extra/missed) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in runs:
        a = {x["threads"]: x for x in r["aabb"]}
        p = r["peer"]
        fcl = r["fcl"]
        fcl_text = "n/a (one object)" if fcl is None and r["self"] and r["scene"].startswith("cloth") else (
            "not run" if fcl is None else f'{fcl["ms"]:,.0f} ({fcl["pairs"]:,.0f}; {fcl["extra"]}/{fcl["missed"]})')
        print(f'| {r["scene"]} | {"on" if r["self"] else "off"} | {r["triangles"]:,} | {",".join(map(str, r["frames"]))} '
              f'| {a[1]["ms"]:,.1f} | {a[2]["ms"]:,.1f} '
              f'| {p["ms"]:,.1f} ({p["refit_ms"]:,.0f} / {p["collide_ms"]:,.0f} / {p["narrow_ms"]:,.0f}) '
              f'| {p["embree_candidates"]:,.0f} | {a[2]["candidates"]:,.0f} | {a[2]["colliding"]:,.0f} | {fcl_text} '
              f'| {p["ms"] / a[1]["ms"]:.2f}x | {p["ms"] / a[2]["ms"]:.2f}x | {p["extra"]}/{p["missed"]} |')
    print()
    print("Where aabb's frame goes (2 threads, means over the timed frames, ms):")
    print()
    print("| scene | self | refit | rebuild | traversal | narrow | total | exact tests | fallbacks / test |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in runs:
        a = {x["threads"]: x for x in r["aabb"]}[2]
        per = a["exact_fallbacks"] / a["exact_tests"] if a["exact_tests"] else 0
        print(f'| {r["scene"]} | {"on" if r["self"] else "off"} | {a["refit_ms"]:,.1f} | {a["rebuild_ms"]:,.1f} '
              f'| {a["traversal_ms"]:,.1f} | {a["narrow_ms"]:,.1f} | {a["ms"]:,.1f} | {a["exact_tests"]:,.0f} | {per:.4f} |')
    print()
    print("The exact tests alone, one thread, per frame (ms), on the Embree candidates that share a vertex index")
    print("(adjacent, within one object) and on the others:")
    print()
    print("| scene | self | adjacent | aabb's test | CGAL peer's | others | aabb's test | CGAL peer's |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in runs:
        x = r.get("narrow_split")
        if not x:
            continue
        print(f'| {r["scene"]} | {"on" if r["self"] else "off"} | {x["adjacent"]:,} | {x["engine_adjacent_ms"]:,.1f} '
              f'| {x["cgal_adjacent_ms"]:,.1f} | {x["other"]:,} | {x["engine_other_ms"]:,.1f} | {x["cgal_other_ms"]:,.1f} |')
    print()
    cloth = [r for r in runs if r["scene"].startswith("cloth")]
    thesis_off = [r for r in runs if not r["scene"].startswith("cloth") and not r["self"]]
    thesis_on = [r for r in runs if not r["scene"].startswith("cloth") and r["self"]]
    thesis_default = [r for r in thesis_off + thesis_on if r["self"] == (r["scene"].split(":")[0] in DEFAULT_SELF_ON)]
    for threads in (2, 1):
        ratio = lambda r: r["peer"]["ms"] / {x["threads"]: x for x in r["aabb"]}[threads]["ms"]
        for label, group in (("cloth + thesis objects only", cloth + thesis_off), ("cloth + thesis self on", cloth + thesis_on),
                             ("cloth + thesis at each data set's own setting (B self on)", cloth + thesis_default)):
            if not group:
                continue
            ratios = [ratio(r) for r in group]
            below = [f'{r["scene"]} {ratio(r):.2f}x' for r in group if ratio(r) < 3]
            print(f"aabb {threads} thr, {label}: geometric mean {geomean(ratios):.2f}x (target >= 10x); "
                  f"scenes under 3x: {', '.join(below) if below else 'none'}")
    low = load(out, "peers-low.jsonl")
    if low:
        print()
        print("The peer with Embree rebuilding every frame (RTC_BUILD_QUALITY_LOW) instead of refitting, cloth scenes:")
        print()
        print("| scene | aabb 2 thr ms | peer (low) ms (rebuild / collide / narrow) | peer (low) / aabb | differs (extra/missed) |")
        print("| --- | --- | --- | --- | --- |")
        for r in low:
            a = {x["threads"]: x for x in r["aabb"]}[2]
            p = r["peer"]
            print(f'| {r["scene"]} | {a["ms"]:,.1f} | {p["ms"]:,.1f} ({p["refit_ms"]:,.0f} / {p["collide_ms"]:,.0f} / {p["narrow_ms"]:,.0f}) '
                  f'| {p["ms"] / a["ms"]:.2f}x | {p["extra"]}/{p["missed"]} |')
    print()
    print("check --stats, every frame, 2 threads: exact_fallbacks per exact test (target <= 0.1)")
    print()
    print("| scene | frames | exact tests | fallbacks | per test | worst frame | refit / rebuild / traversal / narrow / total ms |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for scene, frames, tests, falls, worst, ms in fallbacks(out):
        print(f'| {scene}:large | {frames} | {tests:,} | {falls:,} | {falls / max(tests, 1):.6f} | {worst:.6f} '
              f'| {ms["refit"]:,.1f} / {ms["rebuild"]:,.1f} / {ms["traversal"]:,.1f} / {ms["narrow"]:,.1f} / {ms["total"]:,.1f} |')


if __name__ == "__main__":
    main(sys.argv[1])

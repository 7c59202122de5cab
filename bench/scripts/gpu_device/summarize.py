"""Summarise run.sh's stats: per scene and method, per-frame median/mean ms, GPU stage medians,
colliding pairs, pair-set digest agreement with aabb, adaptive modes and the GL renderer."""
import collections, json, os, statistics, sys

w = sys.argv[1]
md5 = {}
if os.path.exists(os.path.join(w, "pairs_md5.txt")):
    for line in open(os.path.join(w, "pairs_md5.txt")):
        parts = line.split()
        if parts:
            md5[parts[0]] = parts[1] if len(parts) > 1 else ""
rows = []
for name in sorted(os.listdir(os.path.join(w, "stats"))):
    if not name.endswith(".jsonl"):
        continue
    tag = name[:-6]
    scene, method, gl, *extra = tag.split("__")
    frames = [json.loads(l) for l in open(os.path.join(w, "stats", name)) if l.strip()]
    if not frames:
        rows.append((scene, method + ("+" + extra[0].lstrip("-") if extra else ""), gl, 0, None, None, None, None, None, "", "", tag))
        continue
    total = [f["ms"]["total"] for f in frames]
    render = [f["ms"].get("gpu_render", 0) + f["ms"].get("gpu_readback", 0) for f in frames]
    pairs = sum(f["counts"]["colliding_pairs"] for f in frames)
    modes = collections.Counter(int(f["decision"]["mode"]) for f in frames if f.get("decision") and f["decision"].get("mode") is not None)
    renderers = sorted({f["gpu"]["renderer"] for f in frames if f.get("gpu") and f["gpu"].get("renderer")})
    rows.append((scene, method + ("+" + extra[0].lstrip("-") if extra else ""), gl, len(frames), statistics.median(total),
                 statistics.mean(total), statistics.median(total[1:]) if len(total) > 1 else None,
                 statistics.median(render), pairs,
                 " ".join(f"m{k}:{v}" for k, v in sorted(modes.items())), "; ".join(renderers), tag))

print("| scene | method | gl | frames | median ms | mean ms | median ms w/o frame 0 | median gpu render+readback ms | colliding pairs (sum) | pairs == aabb | adaptive modes | renderer |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
fmt = lambda x: "-" if x is None else f"{x:.3f}"
for scene, method, gl, n, med, mean, med1, rend, pairs, modes, renderer, tag in rows:
    ref = md5.get(f"{scene}__aabb__egl")
    mine = md5.get(tag)
    if ref is None:
        same = "?" if mine is None else f"md5 {mine}"
    else:
        same = ("ref " if method == "aabb" and gl == "egl" else ("yes " if mine == ref else "NO ")) + str(mine)
    print(f"| {scene} | {method} | {gl} | {n} | {fmt(med)} | {fmt(mean)} | {fmt(med1)} | {fmt(rend)} | {pairs} | {same} | {modes} | {renderer} |")

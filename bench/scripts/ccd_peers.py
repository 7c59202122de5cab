#!/usr/bin/python3
"""Between-frames detection against the CCD peer (issue 39 point 4), each side in its own process.

Usage: bench/scripts/ccd_peers.py SCENE[:PRESET][@FRAMES] ... [--runs 3] [--threads 2]
           [--self SCENE,...] [--bin build/bench/bench_ccd_peers] [--out RUNS.jsonl]
           [--pairs-dir DIR]

For each scene, --runs rounds run `bench_ccd_peers --method ours` and `--method peer` once each,
each in a fresh process, in alternating order (round 0 ours first, round 1 the peer first, ...),
over every interval of the scene's frames (@N: its first N frames only; @A:B or @A: frames A..B-1
or from A on, as `collidescope check --frames`, e.g. D@0:100 and D@100:, the two halves of D
whose mesh changes at frame 100). Self-collision
follows the scene (as `collidescope check --scene` decides it) unless --self names it. Round 0
writes both sides' pairs (--pairs-dir, removed afterwards) and `bench_ccd_peers --compare` then
counts the pairs the peer missed and its extra pairs, with their diagnosis. Every round of a side
must give the same pairs (digest), else the script stops.

Prints per scene: the medians over the rounds of each side's total ms (the sum of its
intervals' detection times) with min-max, the ratio peer / ours of the medians, the pairs each
reported (summed over the intervals), the peer's missed and extra pairs against ours, and the
pass-throughs each.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# The project's build (bench_ccd_peers is built where Embree 3 is installed), else a separate
# build-peer/.
BINS = [os.path.join(ROOT, build, "bench", "bench_ccd_peers") for build in ("build", "build-peer")]


def scene_args(spec, forced_self):
    name, _, frames = spec.partition("@")
    args = ["--scene", name]
    if frames:
        args += ["--frames", frames]
    if name in forced_self:
        args.append("--self")
    return name, args


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("ccd_peers: %s failed (%d): %s" % (" ".join(command), done.returncode, done.stderr.strip()[-500:]))
    return json.loads(done.stdout.strip().splitlines()[-1]), done.stderr


def spread(values):
    return "%.1f [%.1f-%.1f]" % (statistics.median(values), min(values), max(values))


def measure(args, spec, forced_self, pairs_dir, rows):
    name, base = scene_args(spec, forced_self)
    runs = {"ours": [], "peer": []}
    files = {side: os.path.join(pairs_dir, "%s.%s.bin" % (spec.replace(":", "_").replace("@", "_"), side)) for side in runs}
    for round_ in range(args.runs):
        for side in (("ours", "peer") if round_ % 2 == 0 else ("peer", "ours")):
            command = [args.bin] + base + ["--method", side, "--threads", str(args.threads)]
            if round_ == 0:
                command += ["--pairs", files[side]]
            row, _ = run(command)
            row["round"] = round_
            row["spec"] = spec
            runs[side].append(row)
            rows.append(row)
    for side, side_runs in runs.items():
        if len({r["digest"] for r in side_runs}) != 1:
            sys.exit("ccd_peers: %s: %s gave different pairs in different rounds" % (spec, side))
    compare, diagnosis = run([args.bin] + base + ["--compare", files["ours"], files["peer"]])
    compare["spec"] = spec
    compare["examples"] = diagnosis.strip().splitlines()
    rows.append(compare)
    for path in files.values():
        os.remove(path)
    ours_ms = [r["total_ms"] for r in runs["ours"]]
    peer_ms = [r["total_ms"] for r in runs["peer"]]
    summary = {"summary": True, "spec": spec, "scene": name, "self": runs["ours"][0]["self"], "threads": args.threads,
               "runs": args.runs, "intervals": runs["ours"][0]["intervals"], "triangles": runs["ours"][0]["triangles"],
               "ours_ms": statistics.median(ours_ms), "peer_ms": statistics.median(peer_ms),
               "ratio": statistics.median(peer_ms) / statistics.median(ours_ms),
               "ours_pairs": runs["ours"][0]["pairs"], "peer_pairs": runs["peer"][0]["pairs"],
               "missed": compare["missed"]["count"], "extra": compare["extra"]["count"],
               "ours_pass_throughs": runs["ours"][0]["pass_throughs"], "peer_pass_throughs": runs["peer"][0]["pass_throughs"],
               "ours_unresolved": runs["ours"][0]["unresolved"]}
    rows.append(summary)
    print("%-16s %5s %5s %24s %24s %7s %10s %10s %7s %7s %10s %10s" % (
        spec, "on" if summary["self"] else "off", summary["intervals"], spread(ours_ms), spread(peer_ms),
        "%.2fx" % summary["ratio"], summary["ours_pairs"], summary["peer_pairs"], summary["missed"], summary["extra"],
        summary["ours_pass_throughs"], summary["peer_pass_throughs"]), flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scenes", nargs="+")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--self", default="", help="comma-separated scenes to run with --self")
    parser.add_argument("--bin", default=next((b for b in BINS if os.path.exists(b)), BINS[0]))
    parser.add_argument("--out")
    parser.add_argument("--pairs-dir")
    args = parser.parse_args()
    if not os.access(args.bin, os.X_OK):
        sys.exit("ccd_peers.py: %s not found: build it with `cmake --build build --target bench_ccd_peers` "
                 "(it needs Embree 3, libembree-dev) or give --bin" % args.bin)
    forced_self = set(filter(None, args.self.split(",")))
    pairs_dir = args.pairs_dir or tempfile.mkdtemp(prefix="ccd_peers.")
    rows = []
    print("threads %d, runs %d; ms: the sum over the intervals, median [min-max] over the runs" % (args.threads, args.runs))
    print("%-16s %5s %5s %24s %24s %7s %10s %10s %7s %7s %10s %10s" % (
        "scene", "self", "intvl", "ours ms", "peer ms", "peer/us", "ours pairs", "peer pairs", "missed", "extra",
        "ours pass", "peer pass"))
    try:
        for spec in args.scenes:
            measure(args, spec, forced_self, pairs_dir, rows)
    finally:
        if args.out:
            with open(args.out, "w") as out:
                for row in rows:
                    out.write(json.dumps(row) + "\n")
        if not args.pairs_dir:
            shutil.rmtree(pairs_dir, ignore_errors=True)


if __name__ == "__main__":
    main()

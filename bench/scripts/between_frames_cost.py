#!/usr/bin/python3
"""What `check --between-frames` costs against a per-frame `check` of the same frames.

Usage: between_frames_cost.py [SCENE[:PRESET][@A:B] ...] [--runs 3] [--threads 2] [--out FILE.jsonl]
                              [--self SCENE,...] [--input PATH ...]

For each scene, runs `collidescope check --scene S -q --exit-zero --threads T` with and without
`--between-frames`, alternating which goes first, --runs times each, and reports the medians of
each run's own total (the per-frame check: the sum of its frames' `total` ms; between frames:
the sum of its intervals' `total` ms, both from the total line), their ratio, and what the
intervals found (pairs touching between frames, pass-throughs, unresolved pairs). Self-collision
follows each scene's setting unless --self names it. --input adds an animated model or other
INPUT (with --self and --fps 30), named by its file. SCENE@A:B (or @A:) runs frames A..B-1 (or
from A on), as `check --frames A:B`: D@0:100 and D@100:, E1@1: cover the thesis sets whose mesh
changes once (which between-frames detection refuses across the change, naming the frame).
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.path.join(ROOT, "build", "app", "collidescope")
# Every built-in scene; D and E1-E4 switch once between a triangle soup and shared vertices (D at
# frame 100, E1-E4 at frame 1), which between-frames detection refuses, naming the frame: they
# run on the frames on either side of the change.
SCENES = ["A", "B", "C", "D@0:100", "D@100:", "E1@1:", "E2@1:", "E3@1:", "E4@1:", "demo", "cloth-rest", "cloth-drape",
          "cloth-crumple", "cloth-slide", "contact-layers", "contact-spheres", "contact-rods", "contact-rollers",
          "coplanar-stack"]


def run(binary, target, threads, between, self_collision):
    if os.path.exists(target):
        command = [binary, "check", target, "--fps", "30"]
    else:
        name, _, frames = target.partition("@")
        command = [binary, "check", "--scene", name] + (["--frames", frames] if frames else [])
    command += ["-q", "--exit-zero", "--threads", str(threads)]
    if self_collision:
        command.append("--self")
    if between:
        command.append("--between-frames")
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError("%s: exit %d: %s" % (" ".join(command), result.returncode, result.stderr.strip()[-300:]))
    line = result.stderr.strip().splitlines()[-1]
    if between:
        found = re.search(r"total: (\d+) intervals, \d+ with contact, (\d+) pairs touching between frames, (\d+) "
                          r"pass-throughs.*?; ([0-9.]+) ms(; (\d+) pairs reported without)?", line)
        return {"ms": float(found.group(4)), "count": int(found.group(1)), "pairs": int(found.group(2)),
                "pass_throughs": int(found.group(3)), "unresolved": int(found.group(6) or 0)}
    found = re.search(r"total: (\d+) frames, \d+ with collisions, (\d+) colliding pairs.*, ([0-9.]+) ms", line)
    return {"ms": float(found.group(3)), "count": int(found.group(1)), "pairs": int(found.group(2))}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scenes", nargs="*", default=SCENES)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--self", default="", help="comma-separated scenes to run with --self")
    parser.add_argument("--input", action="append", default=[], help="an INPUT file, run with --self --fps 30")
    parser.add_argument("--out")
    parser.add_argument("--binary", default=BIN, help="the collidescope to time (default: build/app/collidescope)")
    args = parser.parse_args()
    forced_self = set(filter(None, args.self.split(",")))
    rows = []
    print("%-22s %6s %12s %10s %14s %7s %12s %8s %10s" % ("scene", "frames", "pairs/frame", "check ms", "between ms",
                                                        "ratio", "pairs/intv", "passes", "unresolved"))
    for target in args.scenes + args.input:
        self_collision = target.partition("@")[0] in forced_self or target in args.input
        per_frame, between = [], []
        try:
            for round_ in range(args.runs):
                for mode in ((False, True) if round_ % 2 == 0 else (True, False)):
                    (between if mode else per_frame).append(run(args.binary, target, args.threads, mode, self_collision))
        except RuntimeError as error:  # a scene between-frames cannot take (a topology change): said, then the next
            print("%-22s %s" % (os.path.basename(target), str(error).splitlines()[-1][-200:]))
            continue
        check_ms = statistics.median(r["ms"] for r in per_frame)
        between_ms = statistics.median(r["ms"] for r in between)
        last = between[-1]
        row = {"scene": os.path.basename(target), "binary": args.binary, "threads": args.threads, "runs": args.runs, "self": self_collision,
               "frames": per_frame[0]["count"], "pairs": per_frame[0]["pairs"], "check_ms": check_ms,
               "intervals": last["count"], "between_ms": between_ms, "ratio": between_ms / check_ms if check_ms > 0 else 0,
               "between_pairs": last["pairs"], "pass_throughs": last["pass_throughs"], "unresolved": last["unresolved"]}
        rows.append(row)
        print("%-22s %6d %12.0f %10.1f %14.1f %6.1fx %12.0f %8d %10d" % (
            row["scene"] + (" (self)" if self_collision else ""), row["frames"], row["pairs"] / max(row["frames"], 1),
            check_ms, between_ms, row["ratio"], row["between_pairs"] / max(row["intervals"], 1), row["pass_throughs"],
            row["unresolved"]))
        sys.stdout.flush()
    if args.out:
        with open(args.out, "w") as out:
            for row in rows:
                out.write(json.dumps(row) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())

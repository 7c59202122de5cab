#!/usr/bin/python3
"""What `check --regions` adds to a `check` run, per built-in scene.

Usage: regions_cost.py [SCENE[:PRESET] ...] [--runs 3] [--threads 2] [--out FILE.jsonl]
                       [--binary COLLIDESCOPE]

For each scene, runs `collidescope check --scene S -q --exit-zero --threads T` with and without
`--regions /dev/null`, alternating which goes first, --runs times each. Reports the median wall
time of each, the median of check's own total (the sum of its frames' `total` ms, from its
total line), and the regions' cost as (wall with - wall without) / check total: what finding,
following and writing the regions adds to the frames' time, writing included; and the time check reports for finding and following
them alone, against the same total. Default scenes: every built-in
scene at its default preset. --binary runs another build (an older commit's, for an A/B in
one sitting); the default is build/app/collidescope of this checkout.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = [os.path.join(ROOT, "build", "app", "collidescope")]  # --binary replaces it
SCENES = ["A", "B", "C", "D", "E1", "E2", "E3", "E4", "demo", "cloth-rest", "cloth-drape", "cloth-crumple",
          "cloth-slide", "contact-layers", "contact-spheres", "contact-rods", "contact-rollers", "coplanar-stack"]


def run(scene, threads, regions):
    command = [BIN[0], "check", "--scene", scene, "-q", "--exit-zero", "--threads", str(threads)]
    if regions:
        command += ["--regions", "/dev/null"]
    start = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if result.returncode != 0:
        sys.exit("%s: exit %d: %s" % (" ".join(command), result.returncode, result.stderr.strip()[-300:]))
    total = re.search(r"total: (\d+) frames, \d+ with collisions, (\d+) colliding pairs.*, ([0-9.]+) ms", result.stderr)
    found = re.search(r"regions over the run \(found and followed in ([0-9.]+) ms\)", result.stderr)
    return wall, int(total.group(1)), int(total.group(2)), float(total.group(3)), float(found.group(1)) if found else 0.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scenes", nargs="*", default=SCENES)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--out")
    parser.add_argument("--binary", help="the collidescope to measure (default build/app/collidescope)")
    args = parser.parse_args()
    if args.binary:
        BIN[0] = os.path.abspath(args.binary)
    rows = []
    print("%-24s %7s %11s %10s %10s %10s %8s %10s %8s" % ("scene", "frames", "pairs/frame", "check ms", "wall s", "+regions s",
                                                        "added", "regions ms", "compute"))
    for scene in args.scenes:
        plain, with_regions, totals, found = [], [], [], []
        frames = pairs = 0
        for round_ in range(args.runs):
            for regions in ((False, True) if round_ % 2 == 0 else (True, False)):
                wall, frames, pairs, total, regions_ms = run(scene, args.threads, regions)
                (with_regions if regions else plain).append(wall)
                (found if regions else totals).append(regions_ms if regions else total)
        check_ms = statistics.median(totals)
        added = (statistics.median(with_regions) - statistics.median(plain)) * 1000 / check_ms if check_ms > 0 else 0
        row = {"scene": scene, "threads": args.threads, "runs": args.runs, "frames": frames, "pairs": pairs,
               "check_total_ms": check_ms, "wall_s": statistics.median(plain),
               "wall_regions_s": statistics.median(with_regions), "added": added,
               "regions_ms": statistics.median(found), "compute": statistics.median(found) / check_ms if check_ms > 0 else 0}
        rows.append(row)
        print("%-24s %7d %11.0f %10.1f %10.3f %10.3f %7.0f%% %10.1f %7.0f%%" % (
            scene, frames, pairs / max(frames, 1), check_ms, row["wall_s"], row["wall_regions_s"], 100 * added,
            row["regions_ms"], 100 * row["compute"]))
        sys.stdout.flush()
    if args.out:
        with open(args.out, "w") as out:
            for row in rows:
                out.write(json.dumps(row) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())

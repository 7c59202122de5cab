#!/usr/bin/python3
"""Adaptive methods against two oracle-bests, from a `collidescope bench` frames.csv.

Usage: /usr/bin/python3 bench/scripts/bench_oracle.py OUT/frames.csv

Per scene: each method's total ms, then for every adaptive method (name starting with
"adaptive") its total over
  - the oracle over every fixed method of the run (what bench's "x oracle" column reports), and
  - the oracle over the methods the decision system chooses among (aabb, gpu, hybrid; the
    decision system's GPU 1 and GPU 2 are both the `gpu` method's cull),
each the sum over frames of the fastest such method's time on that frame.
"""

import csv
import sys
from collections import defaultdict

CANDIDATES = ("aabb", "gpu", "hybrid")


def main(path):
    frames = defaultdict(dict)  # (scene, preset, frame) -> method -> ms
    order = []
    with open(path, newline="") as handle:
        for row in csv.DictReader(handle):
            key = (row["scene"], row["preset"], int(row["frame"]))
            frames[key][row["method"]] = float(row["ms_total"])
            if row["method"] not in order:
                order.append(row["method"])
    scenes = sorted({(s, p) for (s, p, _) in frames}, key=lambda sp: (sp[0], sp[1]))
    print("scene,method,total_ms,x_oracle_all_fixed,x_oracle_candidates")
    for scene, preset in scenes:
        keys = sorted(k for k in frames if k[:2] == (scene, preset))
        totals = defaultdict(float)
        oracle_all = oracle_candidates = 0.0
        for key in keys:
            times = frames[key]
            for method, ms in times.items():
                totals[method] += ms
            fixed = [ms for m, ms in times.items() if not m.startswith("adaptive")]
            chosen = [ms for m, ms in times.items() if m in CANDIDATES]
            oracle_all += min(fixed) if fixed else 0.0
            oracle_candidates += min(chosen) if chosen else 0.0
        for method in order:
            if method not in totals:
                continue
            if method.startswith("adaptive"):
                all_ratio = totals[method] / oracle_all if oracle_all > 0 else float("nan")
                cand_ratio = totals[method] / oracle_candidates if oracle_candidates > 0 else float("nan")
                print(f"{scene}:{preset},{method},{totals[method]:.3f},{all_ratio:.3f},{cand_ratio:.3f}")
            else:
                print(f"{scene}:{preset},{method},{totals[method]:.3f},,")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])

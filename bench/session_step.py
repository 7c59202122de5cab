#!/usr/bin/python3
"""Session.step from Python against the same C++ step, in one run (issue 24's target: Python
costs at most 5% over C++ on a 40k-triangle frame, contiguous float64 arrays).

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/session_step.py [--scene C] [--frames 40]
           [--rounds 7] [--method aabb] [--threads 0]

Data set C (default preset: two sheets, 40,000 triangles). Each round steps a fresh Session
through the same frames twice, alternately first: once from Python (`s.step(positions)`, timed
around the call: argument checks, views, GIL release, the engine, the pairs array) and once in
a C++ loop over Session::step (collidescope._core._cpp_step_times, views made before the
clock). Per frame, the median over rounds of each; the ratio is the sum of the Python medians
over the sum of the C++ medians, with the per-round ratios' spread.
"""
import argparse
import statistics
import time

import numpy as np

import collidescope
import collidescope._core


def python_times(scene_triangles, frames, options):
    session = collidescope.Session(scene_triangles, **options)
    times = []
    for positions in frames:
        start = time.perf_counter()
        session.step(positions)
        times.append(time.perf_counter() - start)
    return times


def cpp_times(scene_triangles, frames, options):
    session = collidescope.Session(scene_triangles, **options)
    return collidescope._core._cpp_step_times(session, frames)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default="C")
    parser.add_argument("--frames", type=int, default=40)
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--method", default="aabb")
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()
    scene = collidescope.scene(args.scene)
    triangles = scene.triangles()
    frames = [[np.ascontiguousarray(p, dtype=np.float64) for p in scene.positions(f)] for f in range(args.frames)]
    options = {"method": args.method, "threads": args.threads}
    python_times(triangles, frames[:3], options)  # warm-up: TBB's threads, page faults
    runs = {"python": [], "cpp": []}
    for r in range(args.rounds):
        order = ("python", "cpp") if r % 2 == 0 else ("cpp", "python")
        for side in order:
            run = python_times if side == "python" else cpp_times
            runs[side].append(run(triangles, frames, options))
    medians = {side: [statistics.median(t[f] for t in runs[side]) for f in range(args.frames)] for side in runs}
    total = {side: sum(medians[side]) for side in runs}
    per_round = [sum(p) / sum(c) for p, c in zip(runs["python"], runs["cpp"])]
    count = sum(len(t) for t in triangles)
    print("scene %s: %d triangles, %d frames, method %s, threads %d, %d rounds"
          % (args.scene, count, args.frames, args.method, args.threads, args.rounds))
    print("C++ Session::step:    %.3f ms per frame (sum of per-frame medians / frames)" % (1e3 * total["cpp"] / args.frames))
    print("Python Session.step:  %.3f ms per frame" % (1e3 * total["python"] / args.frames))
    print("ratio python / C++:   %.4f (per round: min %.4f, median %.4f, max %.4f)"
          % (total["python"] / total["cpp"], min(per_round), statistics.median(per_round), max(per_round)))


if __name__ == "__main__":
    main()

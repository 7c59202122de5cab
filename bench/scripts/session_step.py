#!/usr/bin/python3
"""Session.step from Python against the same C++ step, in one run (issue 24's target: Python
costs at most 5% over C++ on a 40k-triangle frame, contiguous float64 arrays).

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/scripts/session_step.py [--scene C] [--frames 40]
           [--rounds 7] [--method aabb] [--threads 0]

Data set C (default preset: two sheets, 40,000 triangles). Each round steps a fresh Session
through the same frames twice, alternately first: once from Python (`s.step(positions)`, timed
around the call: argument checks, views, GIL release, the engine, the pairs array) and once in
a C++ loop over Session::step (collidescope._core._cpp_step_times, views made before the
clock). Per frame, the median over rounds of each; the ratio is the sum of the Python medians
over the sum of the C++ medians, with the per-round ratios' spread. On a shared machine that
ratio carries the noise of a 10-50 ms frame, so the script also measures what Python adds per
call on a tiny scene (microseconds, where the engine's time and noise are small) and states
it as a share of the large frame's C++ step.

The float64 C-contiguous arrays reach the engine with no copy (counts.positions_copied_bytes
is 0, printed); the last line times the same C++ loop on float32 copies of the frames, which
the session converts (24 bytes per vertex), against the float64 ones in one run: what a copy
of the positions per step costs, which the zero-copy path does not pay.
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


def copied_bytes(scene_triangles, frames, options):
    """counts.positions_copied_bytes of one Python step on FRAMES[0]."""
    session = collidescope.Session(scene_triangles, **options)
    session.step(frames[0])
    return session.stats["counts"]["positions_copied_bytes"]


def copy_cost(spec, frame_count, rounds, options):
    """Per-frame medians over ROUNDS of the C++ step on float64 frames (viewed in place) and
    on float32 copies of them (converted), alternating which runs first; and the bytes each
    copies per frame."""
    scene = collidescope.scene(spec)
    frame_count = min(frame_count, len(scene))
    triangles = scene.triangles()
    doubles = [[np.ascontiguousarray(p, dtype=np.float64) for p in scene.positions(f)] for f in range(frame_count)]
    frames = {"float64": doubles, "float32": [[p.astype(np.float32) for p in f] for f in doubles]}
    runs = {"float64": [], "float32": []}
    for r in range(rounds):
        for dtype in (("float64", "float32") if r % 2 == 0 else ("float32", "float64")):
            runs[dtype].append(cpp_times(triangles, frames[dtype], options))
    medians = {d: [statistics.median(t[f] for t in runs[d]) for f in range(frame_count)] for d in runs}
    copied = {d: copied_bytes(triangles, frames[d], options) for d in frames}
    return medians, copied


def compare(spec, frame_count, rounds, options):
    """Per-frame medians over ROUNDS of the Python and the C++ step times, and the per-round
    Python / C++ ratios."""
    scene = collidescope.scene(spec)
    frame_count = min(frame_count, len(scene))
    triangles = scene.triangles()
    frames = [[np.ascontiguousarray(p, dtype=np.float64) for p in scene.positions(f)] for f in range(frame_count)]
    python_times(triangles, frames[:3], options)  # warm-up: TBB's threads, page faults
    runs = {"python": [], "cpp": []}
    for r in range(rounds):
        for side in (("python", "cpp") if r % 2 == 0 else ("cpp", "python")):
            run = python_times if side == "python" else cpp_times
            runs[side].append(run(triangles, frames, options))
    medians = {side: [statistics.median(t[f] for t in runs[side]) for f in range(frame_count)] for side in runs}
    per_round = [sum(p) / sum(c) for p, c in zip(runs["python"], runs["cpp"])]
    return sum(len(t) for t in triangles), frame_count, medians, per_round


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default="C")
    parser.add_argument("--frames", type=int, default=40)
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--method", default="aabb")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--overhead-scene", default="demo:small",
                        help="a tiny scene on which the per-call overhead is measured in microseconds")
    args = parser.parse_args()
    options = {"method": args.method, "threads": args.threads}
    count, frames, medians, per_round = compare(args.scene, args.frames, args.rounds, options)
    total = {side: sum(medians[side]) for side in medians}
    print("scene %s: %d triangles, %d frames, method %s, threads %d, %d rounds"
          % (args.scene, count, frames, args.method, args.threads, args.rounds))
    print("C++ Session::step:    %.3f ms per frame (sum of per-frame medians / frames)" % (1e3 * total["cpp"] / frames))
    print("Python Session.step:  %.3f ms per frame" % (1e3 * total["python"] / frames))
    print("ratio python / C++:   %.4f (per round: min %.4f, median %.4f, max %.4f)"
          % (total["python"] / total["cpp"], min(per_round), statistics.median(per_round), max(per_round)))
    # What Python adds per call, in microseconds, where the engine's own time (and its noise) is
    # small: the median over frames of the per-frame median difference.
    tiny_count, tiny_frames, tiny, _ = compare(args.overhead_scene, 1000, 4 * args.rounds, options)
    added = statistics.median(p - c for p, c in zip(tiny["python"], tiny["cpp"]))
    print("overhead per call on %s (%d triangles, %d frames): %.1f us (C++ step %.1f us); "
          "that is %.3f%% of the C++ step on %s"
          % (args.overhead_scene, tiny_count, tiny_frames, 1e6 * added, 1e6 * statistics.median(tiny["cpp"]),
             100 * added / (total["cpp"] / frames), args.scene))
    medians, copied = copy_cost(args.scene, args.frames, args.rounds, options)
    extra = statistics.median(s - d for s, d in zip(medians["float32"], medians["float64"]))
    print("C++ step from float64 (%d bytes copied per frame): %.3f ms; from float32 (%d bytes converted): "
          "%.3f ms; the conversion adds %.1f us per frame (median over frames)"
          % (copied["float64"], 1e3 * statistics.mean(medians["float64"]), copied["float32"],
             1e3 * statistics.mean(medians["float32"]), 1e6 * extra))


if __name__ == "__main__":
    main()

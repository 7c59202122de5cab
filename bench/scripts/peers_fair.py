#!/usr/bin/python3
"""The fair peer comparison: ours against Embree + CGAL, each side in a process of its own.

Usage: bench/scripts/peers_fair.py SCENE... [--threads 1,2] [--runs 5] [--frames SPEC]
           [--self on|off|scene] [--bin build/bench/bench_embree_cgal_peers] [--fcl]
           [--out RUNS.jsonl] [--target 3] [--geomean-target 10]

SCENE is a built-in scene (`cloth-slide:large`) or an input `collidescope check` takes (a
scene.json manifest, a frame pattern); --frames is passed on (`all`, or a list `0,3,7`; the
default is 5 frames spread over the animation). For every scene and thread count, each of
--runs rounds runs `aabb` and the peer once, each in a fresh process of its own
(bench_embree_cgal_peers --only aabb|peer), in alternating order (round 0: ours first, round 1:
the peer first, ...), so neither side always meets a warm or a cold machine. Both sides run on
the same number of threads in every stage (the engine's thread limit; Embree's `threads`
setting and a TBB limit for the peer's narrow phase). Every process prints a digest of its
pairs on every timed frame: all digests of a scene must be equal (the peer is exact, and so are
we), else the run fails.

Prints, per scene and thread count, the medians over the rounds of each side's mean ms per
frame with their spread (min-max), the ratio peer / ours (median of the rounds' ratios, with
their min-max), and whether it meets --target; then, per thread count, the geometric mean of
the median ratios against --geomean-target. With --fcl, FCL (between objects only: it has no
self-collision, so its figure is not comparable where self pairs exist) runs in a third
process per round. Exit status: 0 when every digest agreed, 2 when any differed, 1 on a
failed run.
"""
import argparse
import json
import math
import statistics
import subprocess
import sys


def side_command(args, scene, side, threads):
    command = [args.bin]
    if "/" in scene or scene.endswith(".json"):
        command.append(scene)
    else:
        command += ["--scene", scene]
    command += ["--only", side, "--threads", str(threads), "--self", args.self, "--no-split", "--no-fcl"]
    if args.frames:
        command += ["--frames", args.frames]
    return command


def run_side(args, scene, side, threads):
    done = subprocess.run(side_command(args, scene, side, threads), capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("peers_fair: %s %s at %d threads failed (%d): %s" % (scene, side, threads, done.returncode,
                                                                      done.stderr.strip()))
    return json.loads(done.stdout.strip().splitlines()[-1])


def spread(values):
    return "%.2f [%.2f-%.2f]" % (statistics.median(values), min(values), max(values))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scenes", nargs="+")
    parser.add_argument("--threads", default="1,2")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--frames", default="")
    parser.add_argument("--self", default="scene", choices=["on", "off", "scene"])
    parser.add_argument("--bin", default="build/bench/bench_embree_cgal_peers")
    parser.add_argument("--fcl", action="store_true")
    parser.add_argument("--out", default="")
    parser.add_argument("--target", type=float, default=3.0)
    parser.add_argument("--geomean-target", type=float, default=10.0)
    args = parser.parse_args()
    if args.runs < 1:
        sys.exit("peers_fair: --runs must be at least 1")
    threads_list = [int(t) for t in args.threads.split(",")]
    out = open(args.out, "w") if args.out else None
    digests_agree = True
    ratios = {t: [] for t in threads_list}
    print("| scene | triangles | threads | ours ms | peer ms | peer / ours | %gx |" % args.target)
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for scene in args.scenes:
        for threads in threads_list:
            runs = {"aabb": [], "peer": [], "fcl": []}
            for round_ in range(args.runs):
                sides = ["aabb", "peer"] if round_ % 2 == 0 else ["peer", "aabb"]
                if args.fcl:
                    sides.append("fcl")
                for side in sides:
                    result = run_side(args, scene, side, threads)
                    result["round"] = round_
                    runs[side].append(result)
                    if out:
                        out.write(json.dumps(result) + "\n")
                        out.flush()
            digests = {r["digest"] for r in runs["aabb"] + runs["peer"]}
            if len(digests) != 1:
                digests_agree = False
                print("peers_fair: %s at %d threads: the pairs differ between runs or sides (digests %s)"
                      % (scene, threads, sorted(digests)), file=sys.stderr)
            ours = [r["run"]["ms"] for r in runs["aabb"]]
            peer = [r["run"]["ms"] for r in runs["peer"]]
            by_round = [p / o for o, p in zip(ours, peer) if o > 0]
            ratio = statistics.median(by_round) if by_round else float("nan")
            ratios[threads].append(ratio)
            met = "met" if ratio >= args.target else "**not met**"
            print("| %s | %d | %d | %s | %s | %.2fx [%.2f-%.2f] | %s |"
                  % (scene, runs["aabb"][0]["triangles"], threads, spread(ours), spread(peer), ratio,
                     min(by_round), max(by_round), met))
            if args.fcl:
                fcl = [r["run"]["ms"] for r in runs["fcl"]]
                print("|   FCL (between objects only) | | %d | | %s | %.2fx | |"
                      % (threads, spread(fcl), statistics.median(fcl) / statistics.median(ours)))
            sys.stdout.flush()
    for threads in threads_list:
        values = [r for r in ratios[threads] if r > 0 and not math.isnan(r)]
        if not values:
            continue
        geomean = math.exp(sum(math.log(r) for r in values) / len(values))
        met = sum(1 for r in values if r >= args.target)
        print("%d thread%s: %d of %d scenes at %gx or more; geometric mean %.2fx (target %gx: %s)"
              % (threads, "" if threads == 1 else "s", met, len(values), args.target, geomean, args.geomean_target,
                 "met" if geomean >= args.geomean_target else "not met"))
    if out:
        out.close()
    return 0 if digests_agree else 2


if __name__ == "__main__":
    sys.exit(main())

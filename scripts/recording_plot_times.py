#!/usr/bin/python3
"""Plots per-frame time coloured by the mode (or method) in force.

Usage: recording_plot_times.py RUN.h5 [-o times.png] [--stage total]

One point per frame (x: the frame's time in seconds from /frames/time when the recording has
it (schema 1.4: an animated model or point cache), else the scene frame number; y: the
stage's milliseconds from /frames/ms/<stage>),
coloured by the decision system's mode (collidescope.open's stats["mode"], from
/frames/decision/mode, schema 1.2, on the frames it decided: "mode 1" / "mode 2") and by /frames/method on the others, with a legend. Writes a PNG
(matplotlib, Agg).
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from recording_common import open_recording  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    parser.add_argument("recording")
    parser.add_argument("-o", "--output", default="times.png")
    parser.add_argument("--stage", default="total", help="a dataset of /frames/ms (default total)")
    args = parser.parse_args()
    with open_recording(args.recording) as rec:
        stats = rec.stats
        if args.stage not in stats["ms"]:
            sys.exit("%s: no stage %s (stages: %s)" % (args.recording, args.stage, ", ".join(stats["ms"])))
        n = len(rec)
        # Time where the inputs gave it, frame numbers otherwise.
        times = stats["time"]
        xs_all = times if times is not None else stats["frame"]
        xlabel = "time (%s)" % rec.unit("frames/time") if times is not None else "frame"
        ms = stats["ms"][args.stage]
        unit = rec.unit("frames/ms/" + args.stage)
        # The decision system's mode on the frames it decided, the method on the others.
        per_frame = ["mode %d" % m if m else str(name) for m, name in zip(stats["mode"], stats["method"])]
    fig, ax = plt.subplots(figsize=(10, 4))
    for name in sorted(set(per_frame)):
        xs = [x for x, m in zip(xs_all, per_frame) if m == name]
        ys = [y for y, m in zip(ms, per_frame) if m == name]
        ax.plot(xs, ys, "o", markersize=3, label=name)
    ax.plot(xs_all, ms, "-", color="0.8", linewidth=0.8, zorder=0)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("%s (%s)" % (args.stage, unit))
    ax.set_title("%s: %s per frame, coloured by mode or method" % (args.recording, args.stage))
    ax.legend(title="mode / method")
    fig.tight_layout()
    fig.savefig(args.output, dpi=100)
    print("wrote %s (%d frames; x axis: %s)" % (args.output, n, xlabel))
    return 0


if __name__ == "__main__":
    sys.exit(main())

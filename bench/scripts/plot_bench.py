#!/usr/bin/python3
"""Draws the plots of a `collidescope bench` run: time per frame per method, one SVG per scene.

Usage: plot_bench.py DIR

Reads DIR/frames.csv (written by `collidescope bench`, which runs this script itself) and
writes DIR/time_<scene>_<preset>.svg for every scene in it, in the style of the thesis's
Figures 5.6-5.13: one line per method (the frame's total milliseconds), a logarithmic axis when
the methods differ by more than 30x, and under the axis one strip per adaptive method showing
the mode in force on each frame (Mode 1 AABB blue, the hybrid framework green, Mode 2 GPU
orange). The SVGs keep their text as text and carry no date, so two runs on the same numbers
give the same files.

This is the project's one plotting stack (matplotlib, Agg); the recording scripts in scripts/
use it too.
"""
import csv
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.fonttype"] = "none"  # text stays searchable text
matplotlib.rcParams["svg.hashsalt"] = "collidescope-bench"  # stable element ids
import matplotlib.pyplot as plt  # noqa: E402

PALETTE = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"]
DECISION_COLOURS = OrderedDict([("mode 1", "#9ecae1"), ("hybrid", "#74c476"), ("mode 2", "#fd8d3c")])
DECISION_LABELS = {"mode 1": "Mode 1 (AABB)", "hybrid": "hybrid framework", "mode 2": "Mode 2 (GPU)"}


def read_scenes(frames_csv):
    """{(scene, preset): {"triangles": n, "methods": {method: [(frame, ms, decision)]}}} in file order."""
    scenes = OrderedDict()
    with open(frames_csv, newline="") as handle:
        rows = csv.DictReader(handle)
        for column in ("scene", "preset", "method", "frame", "ms_total", "decision", "triangles"):
            if column not in rows.fieldnames:
                raise ValueError("%s: no column %s (written by an older collidescope?)" % (frames_csv, column))
        for line, row in enumerate(rows, start=2):
            try:
                point = (int(row["frame"]), float(row["ms_total"]), row["decision"])
                triangles = int(row["triangles"])
            except ValueError as error:
                raise ValueError("%s:%d: %s" % (frames_csv, line, error))
            scene = scenes.setdefault((row["scene"], row["preset"]), {"triangles": triangles, "methods": OrderedDict()})
            scene["methods"].setdefault(row["method"], []).append(point)
    return scenes


def plot_scene(name, preset, scene, output):
    methods = scene["methods"]
    adaptive = [m for m in methods if m.startswith("adaptive")]
    totals = [ms for points in methods.values() for _, ms, _ in points]
    positive = [ms for ms in totals if ms > 0]
    log = bool(positive) and min(positive) < max(positive) / 30

    fig = plt.figure(figsize=(7.6, 4.2 + 0.12 * len(adaptive)))
    strip_height = 0.04 * len(adaptive)
    ax = fig.add_axes([0.09, 0.16 + strip_height, 0.68, 0.74 - strip_height])
    for index, (method, points) in enumerate(methods.items()):
        ax.plot([f for f, _, _ in points], [ms for _, ms, _ in points], color=PALETTE[index % len(PALETTE)],
                linewidth=1.8, label=method)
    if log:
        ax.set_yscale("log")
    else:
        ax.set_ylim(bottom=0)
    ax.set_xlabel("frame")
    ax.set_ylabel("time per frame (ms%s)" % (", log scale" if log else ""))
    ax.set_title("Data set %s (%s, %d triangles): time per frame" % (name, preset, scene["triangles"]),
                 fontsize=11, loc="left")
    ax.grid(axis="y", color="#ddd")
    handles = ax.get_legend_handles_labels()

    # One strip per adaptive method under the axis: the mode in force on each frame.
    for row, method in enumerate(adaptive):
        strip = fig.add_axes([0.09, 0.03 + 0.04 * row, 0.68, 0.03], sharex=ax)
        for frame, _, decision in methods[method]:
            if decision in DECISION_COLOURS:
                strip.axvspan(frame - 0.5, frame + 0.5, color=DECISION_COLOURS[decision], linewidth=0)
        strip.set_yticks([])
        strip.tick_params(labelbottom=False, bottom=False)
        strip.text(1.01, 0.5, "mode: " + method, transform=strip.transAxes, fontsize=8, va="center")
    if adaptive:
        handles = (handles[0] + [plt.Rectangle((0, 0), 1, 1, color=c) for c in DECISION_COLOURS.values()],
                   handles[1] + [DECISION_LABELS[d] for d in DECISION_COLOURS])
    fig.legend(*handles, loc="upper left", bbox_to_anchor=(0.78, 0.9), frameon=False, fontsize=9)
    fig.savefig(output, format="svg", metadata={"Date": None})
    plt.close(fig)


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__.split("\n")[2] + "\n")
        return 2
    folder = argv[1]
    try:
        scenes = read_scenes(os.path.join(folder, "frames.csv"))
    except (OSError, ValueError) as error:
        sys.stderr.write("plot_bench.py: %s\n" % error)
        return 2
    for (name, preset), scene in scenes.items():
        plot_scene(name, preset, scene, os.path.join(folder, "time_%s_%s.svg" % (name, preset)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

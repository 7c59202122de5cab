#!/usr/bin/python3
"""Shows a recorded depth buffer of the GPU cull.

Usage: recording_depth.py RUN.h5 [--frame N] [--image I] [-o depth.png]

Depth buffers are recorded (schema 1.2, /gpu/depth) by the methods that run the GPU cull when
`record --depth every:N` asks for them: one image per triangle-level view, after its forward
pass. The script draws image I (default 0) of scene frame N (default: the first frame that has
one) as the coordinate along the view axis, in the input's length unit, with a colour bar;
pixels where nothing was drawn are left blank. Without depth images it says "no depth buffers
in this recording" and exits 0.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from recording_common import open_recording  # noqa: E402

AXES = "xyz"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    parser.add_argument("recording")
    parser.add_argument("--frame", type=int, default=None, help="scene frame (default: the first with depth)")
    parser.add_argument("--image", type=int, default=0, help="which image of the frame (default 0)")
    parser.add_argument("-o", "--output", default="depth.png")
    args = parser.parse_args()
    with open_recording(args.recording) as rec:
        frames = [int(f) for f in rec.frames]
        counts = [rec.depth_count(f) for f in frames]
        if sum(counts) == 0:
            print("no depth buffers in this recording (--depth %s)" % rec.attrs.get("depth", "off"))
            return 0
        if args.frame is None:
            row = next(r for r in range(len(frames)) if counts[r] > 0)
        elif args.frame in frames:
            row = frames.index(args.frame)
        else:
            sys.exit("%s: frame %d is not recorded" % (args.recording, args.frame))
        if not 0 <= args.image < counts[row]:
            with_depth = [frames[r] for r in range(len(frames)) if counts[r] > 0]
            sys.exit("%s: frame %d has %d depth images (frames with some: %s)"
                     % (args.recording, frames[row], counts[row], ", ".join(map(str, with_depth[:20]))))
        image = rec.depth(frames[row])[args.image]
        unit = rec.unit("gpu/depth/range")
    near, far = image["near"], image["far"]
    world = np.where(image["depth"] < 1.0, near + image["depth"] * (far - near), np.nan)
    view = image["view"]
    fig, ax = plt.subplots(figsize=(6, 5.2))
    # Row 0 is the bottom row (GL order): origin="lower".
    shown = ax.imshow(world, origin="lower", cmap="viridis", interpolation="nearest")
    bar = fig.colorbar(shown, ax=ax)
    bar.set_label("%s coordinate (%s); nearer = smaller" % (AXES[view], unit))
    ax.set_xlabel("%s (pixels)" % AXES[(view + 1) % 3])
    ax.set_ylabel("%s (pixels)" % AXES[(view + 2) % 3])
    ax.set_title("frame %d: %s view, %s level, %dx%d, %d of %d pixels drawn"
                 % (frames[row], AXES[view], "triangle" if image["level"] == 1 else "object",
                    image["width"], image["height"], int(np.isfinite(world).sum()), world.size), fontsize=9)
    fig.tight_layout()
    fig.savefig(args.output, dpi=100)
    print("wrote %s (frame %d, image %d: %s view; depth %.6g..%.6g %s)"
          % (args.output, frames[row], args.image, AXES[view], near, far, unit))
    return 0


if __name__ == "__main__":
    sys.exit(main())

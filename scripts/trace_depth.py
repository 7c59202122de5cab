#!/usr/bin/python3
"""Shows a recorded depth buffer of the GPU cull.

Usage: trace_depth.py RUN.h5 [--frame N] [-o depth.png]

Depth buffers are recorded by the GPU cull (Mode 2) when `record --depth every:N` asks for
them. Schema 1.0 has no method with a GPU cull yet, so recordings hold none: the script says
"no depth buffers in this recording" and exits 0. The schema slot arrives with Mode 2.
"""
import argparse
import sys

from trace_common import open_recording


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    parser.add_argument("recording")
    parser.add_argument("--frame", type=int, default=None)
    parser.add_argument("-o", "--output", default="depth.png")
    args = parser.parse_args()
    with open_recording(args.recording) as f:
        if "gpu" not in f or "depth" not in f["gpu"]:
            print("no depth buffers in this recording (--depth %s; no GPU cull before Mode 2)"
                  % f.attrs.get("depth", "off"))
            return 0
        sys.exit("%s: depth buffers in a layout these scripts do not know yet" % args.recording)


if __name__ == "__main__":
    sys.exit(main())

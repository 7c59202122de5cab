#!/usr/bin/python3
"""Lists the frames and triangles that collide in a recording.

Usage: recording_pairs.py RUN.h5 [--summary] [--frames A:B]

Default output is `collidescope check --pairs` TSV: frame objA triA objB triB, one line per
colliding pair. --summary prints one line per frame with collisions instead: the frame, its
pair count and the triangles involved per object. --frames keeps scene frames A..B-1.
"""
import argparse
import sys

from recording_common import open_recording


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    parser.add_argument("recording")
    parser.add_argument("--summary", action="store_true", help="one line per frame with collisions")
    parser.add_argument("--frames", default=":", help="scene frames A:B (half-open)")
    args = parser.parse_args()
    first, _, last = args.frames.partition(":")
    out = sys.stdout
    with open_recording(args.recording) as rec:
        for frame in rec.frames:
            if (first and frame < int(first)) or (last and frame >= int(last)):
                continue
            rows = rec.pairs(frame)
            if args.summary:
                if len(rows):
                    tris = {}
                    for a, ta, b, tb in rows:
                        tris.setdefault(int(a), set()).add(int(ta))
                        tris.setdefault(int(b), set()).add(int(tb))
                    per_object = ", ".join("object %d: %d triangles" % (k, len(v)) for k, v in sorted(tris.items()))
                    out.write("frame %d: %d colliding pairs (%s)\n" % (frame, len(rows), per_object))
                continue
            for a, ta, b, tb in rows:
                out.write("%d\t%d\t%d\t%d\t%d\n" % (frame, a, ta, b, tb))
    return 0


if __name__ == "__main__":
    sys.exit(main())

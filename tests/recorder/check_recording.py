"""Reads a recording with h5py alone (no collidescope) and checks it against `check`'s outputs.

Usage: check_recording.py RUN.h5 PAIRS.tsv STATS.jsonl
Exits 0 when the pairs equal the TSV, the counts and methods equal the stats, and every dataset
has a unit; prints what differs and exits 1 otherwise.
"""
import json
import sys

import h5py
import numpy as np


def text(value):
    """A string attribute as str: fixed-length ones (schema 1.2) come back from h5py as bytes."""
    return value.decode("utf-8") if isinstance(value, (bytes, np.bytes_)) else value


def main(path, pairs_tsv, stats_jsonl):
    problems = []
    with h5py.File(path, "r", swmr=True) as f:
        if text(f.attrs["schema"]) != "collidescope-trace" or f.attrs["schema_version_major"] != 1:
            problems.append("schema attributes: %r %r" % (f.attrs.get("schema"), f.attrs.get("schema_version_major")))
        frames = f["frames/index"][:]
        offsets = f["collisions/offsets"][:]
        pairs = f["collisions/pairs"][:]
        rows = []
        for r, frame in enumerate(frames):
            for p in pairs[offsets[r]:offsets[r + 1]]:
                rows.append((int(frame), *map(int, p)))
        expected = []
        with open(pairs_tsv) as tsv:
            for line in tsv:
                expected.append(tuple(int(x) for x in line.split("\t")))
        if rows != expected:
            problems.append("pairs differ: %d in the file, %d in the TSV" % (len(rows), len(expected)))
        methods = h5py.check_enum_dtype(f["frames/method"].dtype)
        names = {code: name for name, code in methods.items()}
        with open(stats_jsonl) as stats:
            for r, line in enumerate(stats):
                record = json.loads(line)
                if int(frames[r]) != record["frame"]:
                    problems.append("frame row %d: %d, stats %d" % (r, frames[r], record["frame"]))
                if names[int(f["frames/method"][r])] != record["method"]:
                    problems.append("method of row %d" % r)
                for name, value in record["counts"].items():
                    if int(f["frames/counts/" + name][r]) != value:
                        problems.append("count %s of row %d" % (name, r))
                for name in record["ms"]:
                    if name not in f["frames/ms"]:
                        problems.append("stage %s missing" % name)
        first = f["objects/0"]
        vertex_count = int(first["topology_vertex_count"][0])
        positions = first["positions"][offsets.size and first["vertex_offsets"][0]:first["vertex_offsets"][1]]
        if positions.shape != (vertex_count, 3) or positions.dtype != np.float32:
            problems.append("positions of object 0, frame row 0: %s %s" % (positions.shape, positions.dtype))

        def check_unit(name, obj):
            if isinstance(obj, h5py.Dataset) and not obj.attrs.get("unit"):
                problems.append("no unit on " + name)
        f.visititems(check_unit)
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))

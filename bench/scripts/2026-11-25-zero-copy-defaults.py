#!/usr/bin/python3
"""Pairs of a Python Session (float64 C-contiguous arrays: the zero-copy step) against
`collidescope check --pairs` on built-in scenes at their default presets, every frame.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/scripts/2026-11-25-zero-copy-defaults.py \
           build/app/collidescope C A B D demo E1 E2 E3 E4
(too slow for ctest on a 2-core machine; the tests run the small presets.)
"""
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python", "tests"))

import numpy as np  # noqa: E402

import collidescope  # noqa: E402
from conftest import check_pairs, session_pairs  # noqa: E402


def main():
    cli, specs = sys.argv[1], sys.argv[2:]
    for spec in specs:
        t0 = time.time()
        scene = collidescope.scene(spec)
        session = collidescope.Session(scene.triangles(), self_collision=scene.self_collision)
        ours = session_pairs(session, scene)
        copied = session.stats["counts"]["positions_copied_bytes"]
        t1 = time.time()
        expected = check_pairs(cli, spec)
        t2 = time.time()
        same = ours.shape == expected.shape and np.array_equal(ours, expected)
        print("%-8s frames %4d pairs %8d check %8d identical %s copied_bytes(last) %d  python %.1fs check %.1fs"
              % (spec, len(scene), len(ours), len(expected), same, copied, t1 - t0, t2 - t1), flush=True)


if __name__ == "__main__":
    main()

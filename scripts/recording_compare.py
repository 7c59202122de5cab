#!/usr/bin/python3
"""Compares two recordings: pairs per frame and time per stage.

Usage: recording_compare.py A.h5 B.h5

Frames are matched by scene frame number. Prints the first frame where the pair sets differ,
each differing frame with the pairs only in A and only in B, and per stage the total
milliseconds of A and B and their ratio B/A. Exits 0 when the same frames have identical
pairs, 1 otherwise (like `collidescope compare`).
"""
import sys

from recording_common import open_recording


def pair_sets(rec):
    return {int(frame): {tuple(map(int, p)) for p in rec.pairs(frame)} for frame in rec.frames}


def main(path_a, path_b):
    with open_recording(path_a) as a, open_recording(path_b) as b:
        sets_a, sets_b = pair_sets(a), pair_sets(b)
        common = sorted(set(sets_a) & set(sets_b))
        differ = [(fr, len(sets_a[fr] - sets_b[fr]), len(sets_b[fr] - sets_a[fr])) for fr in common if sets_a[fr] != sets_b[fr]]
        print("%d frames matched; only in a: %d, only in b: %d" % (len(common), len(sets_a) - len(common), len(sets_b) - len(common)))
        if differ:
            print("first difference at frame %d; %d frames differ" % (differ[0][0], len(differ)))
            print("frame\tonly_in_a\tonly_in_b")
            for row in differ:
                print("%d\t%d\t%d" % row)
        else:
            print("pairs identical in every matched frame")
        rows_a = {int(fr): r for r, fr in enumerate(a.frames)}
        rows_b = {int(fr): r for r, fr in enumerate(b.frames)}
        ms_a, ms_b = a.stats["ms"], b.stats["ms"]
        print("stage\ttotal_a_ms\ttotal_b_ms\tratio_b_over_a")
        for stage in ms_a:
            if stage not in ms_b:
                continue
            total_a = sum(ms_a[stage][rows_a[fr]] for fr in common)
            total_b = sum(ms_b[stage][rows_b[fr]] for fr in common)
            ratio = "%.3f" % (total_b / total_a) if total_a > 0 else "-"
            print("%s\t%.3f\t%.3f\t%s" % (stage, total_a, total_b, ratio))
        same = not differ and len(common) == len(sets_a) == len(sets_b)
    return 0 if same else 1


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))

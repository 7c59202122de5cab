#!/usr/bin/python3
"""Records every animated model of Debian's assimp-testmodels and replays it as a video.

For each model listed in animated_models.txt (beside this script), runs what a user would:

    collidescope record MODEL --self -o run.h5
    collidescope replay run.h5 --video run.mp4

(the video of a clip longer than VIDEO_FRAMES frames made of its first VIDEO_FRAMES, `--frames
:600`) and checks that the recording holds one frame per sample of the clip with its time
(/frames/time in seconds, the fps attribute, the clip's name), that the clip is an MP4 (an
`ftyp` box first, the `moov` index before the media) and that nothing was left half-written.
X/anim_test.x (a bone that names no node) must instead be refused: exit 2, one line on stderr
naming the file, no recording left.

    record_replay_animated.py COLLIDESCOPE [--models DIR] [--list FILE] [--shard I/N]
                              [--jobs J] [--timeout S]

--shard I/N takes every N-th model from the I-th, so the list splits into ctest entries.
A missing corpus is a skip (exit 77) on a developer's machine and a failure under CI
(env CI=true): scripts/setup.sh installs assimp-testmodels.

The list holds the files whose `check` gives more than one frame (regenerate it with
--discover, which runs `check --stats` over the whole corpus).
"""

import argparse
import concurrent.futures
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time

import h5py
import numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "mesh"))
from check_model_corpus import DEFAULT_MODELS, corpus_files, missing_corpus  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REFUSED = {"X/anim_test.x": "names no node"}
VIDEO_FRAMES = 240  # the most frames of a clip encoded as video (8 s at 30 fps; encoding ~14 ms a frame here)


def read_list(path):
    with open(path, encoding="utf-8") as f:
        return [line.strip() for line in f if line.strip() and not line.startswith("#")]


def mp4_boxes(path):
    """The top-level box types of an MP4 file, in order."""
    boxes = []
    with open(path, "rb") as f:
        while True:
            header = f.read(8)
            if len(header) < 8:
                return boxes
            size, kind = struct.unpack(">I4s", header)
            if size == 1:
                size = struct.unpack(">Q", f.read(8))[0]
                f.seek(size - 16, os.SEEK_CUR)
            elif size == 0:
                boxes.append(kind.decode("latin-1"))
                return boxes
            else:
                f.seek(size - 8, os.SEEK_CUR)
            boxes.append(kind.decode("latin-1"))


def run(command, timeout):
    try:
        done = subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "ran past %g s" % timeout
    return done.returncode, done.stderr.decode("utf-8", "replace")


def check_refused(binary, model, path, work, timeout, reason):
    recording = os.path.join(work, "run.h5")
    code, err = run([binary, "record", path, "--self", "-o", recording], timeout)
    lines = err.splitlines() if code is not None else []
    prefix = "collidescope: error: " + path
    if code != 2 or len(lines) != 1 or not lines[0].startswith(prefix) or reason not in lines[0]:
        return "expected exit 2 and one line naming %s (%s), got exit %s: %r" % (path, reason, code, err[:400])
    if os.listdir(work):
        return "a refused record left files behind: %s" % sorted(os.listdir(work))
    return None


def check_round_trip(binary, model, path, work, timeout):
    recording = os.path.join(work, "run.h5")
    video = os.path.join(work, "run.mp4")
    code, err = run([binary, "record", path, "--self", "-q", "-o", recording], timeout)
    if code not in (0, 1):  # 1: collisions found
        return "record: exit %s: %s" % (code, err.strip()[-400:])
    with h5py.File(recording, "r") as f:
        frames = f["frames/index"].shape[0]
        if "time" not in f["frames"]:
            return "record: no /frames/time in the recording of an animated model"
        times = f["frames/time"][...]
        unit = f["frames/time"].attrs.get("unit")
        fps = f.attrs.get("fps")
        clip = f.attrs.get("clip")
    if isinstance(unit, bytes):
        unit = unit.decode()
    if frames < 2 or unit != "s" or fps is None or not fps > 0 or clip is None:
        return "record: %d frames, time unit %r, fps %r, clip %r" % (frames, unit, fps, clip)
    if not numpy.allclose(times, numpy.arange(frames) / fps, rtol=0, atol=1e-9):
        return "record: frame times are not k / fps: %s" % times[:5]
    # A long clip's video is made of its first frames only (MDL (HL1)'s chrome_sphere.mdl holds
    # 6,631: its whole video took 106 s of a 2-core machine, longer than all the other models
    # together); the recording above still holds and times every frame.
    replay = [binary, "replay", recording, "--video", video, "-q"]
    if frames > VIDEO_FRAMES:
        replay += ["--frames", ":%d" % VIDEO_FRAMES]
    code, err = run(replay, timeout)
    if code != 0:
        return "replay --video: exit %s: %s" % (code, err.strip()[-400:])
    boxes = mp4_boxes(video)
    if not boxes or boxes[0] != "ftyp" or "moov" not in boxes or "mdat" not in boxes \
            or boxes.index("moov") > boxes.index("mdat"):
        return "replay --video: not a fast-start MP4 (top-level boxes %s)" % boxes
    leftovers = [name for name in os.listdir(work) if name not in ("run.h5", "run.mp4")]
    if leftovers:
        return "files left behind: %s" % leftovers
    return None


def run_one(binary, models, model, timeout):
    path = os.path.join(models, model)
    work = tempfile.mkdtemp(prefix="collidescope_anim_")
    started = time.monotonic()
    try:
        if model in REFUSED:
            return model, check_refused(binary, model, path, work, timeout, REFUSED[model])
        return model, check_round_trip(binary, model, path, work, timeout)
    finally:
        shutil.rmtree(work, ignore_errors=True)
        print("%s: %.1f s" % (model, time.monotonic() - started), flush=True)


def discover(binary, models, jobs):
    def frames_of(path):
        work = tempfile.mkdtemp(prefix="collidescope_discover_")
        try:
            stats = os.path.join(work, "stats.jsonl")
            code, _ = run([binary, "check", "--quiet", "--exit-zero", "--stats", stats, path], 60)
            if code != 0 or not os.path.exists(stats):
                return path, 0
            with open(stats, encoding="utf-8") as f:
                return path, sum(1 for _ in f)
        finally:
            shutil.rmtree(work, ignore_errors=True)

    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for path, frames in pool.map(frames_of, corpus_files(models)):
            if frames > 1:
                print(os.path.relpath(path, models))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("binary")
    parser.add_argument("--models", default=DEFAULT_MODELS)
    parser.add_argument("--list", default=os.path.join(HERE, "animated_models.txt"))
    parser.add_argument("--shard", default="0/1")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=300.0)
    parser.add_argument("--discover", action="store_true")
    args = parser.parse_args()

    missing = missing_corpus(args.models)
    if missing is not None:
        return missing
    if args.discover:
        discover(args.binary, args.models, args.jobs)
        return 0

    index, count = (int(part) for part in args.shard.split("/"))
    models = (read_list(args.list) + sorted(REFUSED))[index::count]
    missing = [m for m in models if not os.path.isfile(os.path.join(args.models, m))]
    if missing or not models:
        print("FAIL: models missing from %s: %s" % (args.models, missing or "(none selected)"), file=sys.stderr)
        return 1
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(lambda m: run_one(args.binary, args.models, m, args.timeout), models))
    failures = [(m, why) for m, why in results if why]
    for model, why in failures:
        print("FAIL %s: %s" % (model, why), file=sys.stderr)
    print("%d models (shard %s): %d recorded and replayed as video or refused as expected, %d failed"
          % (len(results), args.shard, len(results) - len(failures), len(failures)), file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

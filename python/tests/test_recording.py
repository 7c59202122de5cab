"""collidescope.open: a recording's frames, pairs, positions, stats and depth images, from a
Session's recording, from `collidescope record`, while it is written and after a kill."""
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import collidescope
from conftest import check_pairs, run_cli


def test_a_sessions_recording_holds_its_frames(tmp_path, cli):
    scene = collidescope.scene("C:small")
    path = str(tmp_path / "run.h5")
    stepped, stats = [], []
    with collidescope.Session(scene.triangles(), method="adaptive", record=path, names=scene.objects) as s:
        for frame in range(len(scene)):
            stepped.append(s.step(scene.positions(frame)))
            stats.append(s.stats)
    code, out, err = run_cli(cli, "validate", path)
    assert code == 0, out + err
    rec = collidescope.open(path)
    assert len(rec) == len(scene) and rec.finished
    assert list(rec.frames) == list(range(len(scene)))
    assert rec.objects == scene.objects
    for frame in range(len(scene)):
        assert rec.pairs(frame).dtype == np.int64
        assert np.array_equal(rec.pairs(frame), stepped[frame])
        for obj in range(2):
            assert np.array_equal(rec.positions(frame, obj), scene.positions(frame)[obj].astype(np.float32))
            assert np.array_equal(rec.triangles(frame, obj), scene.triangles(frame)[obj])
    assert sum(len(p) for p in stepped) > 0
    assert np.array_equal(rec.stats["ms"]["total"], [s["ms"]["total"] for s in stats])
    assert np.array_equal(rec.stats["counts"]["colliding_pairs"], [len(p) for p in stepped])
    assert list(rec.stats["method"]) == [s["method"] for s in stats]
    assert list(rec.stats["mode"]) == [s["decision"]["mode"] for s in stats]
    assert rec.depth(0) == []
    with pytest.raises(IndexError, match="frame 16 is not recorded"):
        rec.pairs(16)


def test_a_record_recording_equals_check(tmp_path, cli):
    code, _, err = run_cli(cli, "record", "--scene", "demo:small", "--frames", "4:12", "--method", "aabb",
                           "-o", "run.h5", "-q", cwd=tmp_path)
    assert code == 0, err
    rec = collidescope.open(tmp_path / "run.h5")
    expected = check_pairs(cli, "demo:small", "--frames", "4:12", "--method", "aabb")
    assert list(rec.frames) == list(range(4, 12))
    got = np.vstack([np.hstack([np.full((len(rec.pairs(f)), 1), f), rec.pairs(f)]) for f in rec.frames])
    assert len(expected) > 0 and np.array_equal(got, expected)
    assert set(rec.stats["method"]) == {"aabb"} and not rec.stats["mode"].any()
    assert rec.stats["aabb"]["present"].all()


def test_depth_images(tmp_path, cli):
    code, _, err = run_cli(cli, "record", "--scene", "C:small", "--method", "gpu", "--gpu-resolution", "64",
                           "--depth", "every:2", "--frames", "0:3", "-o", "gpu.h5", "-q", cwd=tmp_path)
    assert code == 0, err
    rec = collidescope.open(tmp_path / "gpu.h5")
    images = rec.depth(2)
    assert images and rec.depth(1) == []
    image = images[0]
    assert image["depth"].shape == (image["height"], image["width"]) == (64, 64)
    assert 0 <= image["depth"].min() < 1 and image["depth"].max() <= 1
    assert rec.stats["gpu"]["present"].all() and (rec.stats["gpu"]["queries"] > 0).all()


WRITER = r"""
import sys, time
import numpy as np
import collidescope
scene = collidescope.scene("C:small")
s = collidescope.Session(scene.triangles(), method="aabb", record=sys.argv[1])
pairs = [s.step(scene.positions(f)) for f in range(int(sys.argv[2]))]
np.savez(sys.argv[1] + ".npz", *pairs)
print("ready", flush=True)
time.sleep(600)
"""


def test_a_recording_being_written_and_then_killed(tmp_path):
    path = str(tmp_path / "live.h5")
    frames = 6
    child = subprocess.Popen([sys.executable, "-c", WRITER, path, str(frames)], stdout=subprocess.PIPE, text=True,
                             env=dict(os.environ))
    try:
        assert child.stdout.readline().strip() == "ready"
        rec = collidescope.open(path)
        deadline = time.time() + 60
        while len(rec.refresh()) < frames and time.time() < deadline:
            time.sleep(0.05)
        assert len(rec) == frames and not rec.finished  # still being written
        rec.close()
    finally:
        child.send_signal(signal.SIGKILL)
        child.wait()
    stepped = np.load(path + ".npz")
    with collidescope.open(path) as rec:
        assert len(rec) == frames and not rec.finished
        for frame in range(frames):
            assert np.array_equal(rec.pairs(frame), stepped["arr_%d" % frame])
        assert rec.stats["ms"]["total"].shape == (frames,)
    assert sum(len(stepped["arr_%d" % f]) for f in range(frames)) > 0


def test_not_a_recording(tmp_path):
    text = tmp_path / "notes.h5"
    text.write_text("not hdf5")
    with pytest.raises(collidescope.RecordingError, match=r"notes.h5: cannot open as HDF5"):
        collidescope.open(text)


def test_a_virtual_join_reads_as_the_whole_run_and_a_missing_part_is_an_error(tmp_path, cli):
    """`join --virtual` leaves the positions in the parts: collidescope.open reads it as the
    whole run, and refuses it (naming the part) when a part is gone, where plain h5py reads
    zeros."""
    import h5py
    record = ("record", "--scene", "D:small", "--method", "aabb", "--threads", "1", "-q")
    for args in (("-o", "whole.h5"), ("--frames", ":5", "-o", "parts/p0.h5"), ("--frames", "5:", "-o", "parts/p1.h5")):
        os.makedirs(tmp_path / "parts", exist_ok=True)
        code, out, err = run_cli(cli, *record, *args, cwd=tmp_path)
        assert code == 0, err
    code, out, err = run_cli(cli, "join", "--virtual", "parts/p0.h5", "parts/p1.h5", "-o", "run.h5", cwd=tmp_path)
    assert code == 0, err
    with collidescope.open(tmp_path / "whole.h5") as whole, collidescope.open(tmp_path / "run.h5") as joined:
        assert list(joined.frames) == list(whole.frames)
        for frame in whole.frames:
            assert np.array_equal(joined.pairs(frame), whole.pairs(frame))
            for k in range(len(whole.objects)):
                assert np.array_equal(joined.positions(frame, k), whole.positions(frame, k))
    os.remove(tmp_path / "parts" / "p1.h5")
    with h5py.File(tmp_path / "run.h5", "r") as f:
        assert f["objects/0/positions"].is_virtual
        assert not f["objects/0/positions"][-1].any()  # HDF5's fill value: why the check exists
    with pytest.raises(collidescope.RecordingError, match=r"run.h5: /\S+ maps rows of parts/p1.h5, which is missing"):
        collidescope.open(tmp_path / "run.h5")


def test_regions_equal_check_regions(tmp_path, cli):
    """record --regions read back: regions(frame), region_curves(frame) and region_tracks()
    hold what `check --regions` wrote for the same frames."""
    import json
    import re
    scene = ["--scene", "E4:small", "--self", "--frames", "0:6"]
    code, _, err = run_cli(cli, "record", *scene, "--regions", "-o", str(tmp_path / "r.h5"), "-q")
    assert code == 0, err
    code, out, err = run_cli(cli, "check", *scene, "--regions", "-", "--exit-zero")
    assert code == 0, err
    lines = [json.loads(line) for line in out.splitlines()]
    with collidescope.open(str(tmp_path / "r.h5")) as rec:
        assert rec.has_regions
        got = []
        for frame in rec.frames:
            regions = rec.regions(frame)
            curves = rec.region_curves(frame)
            for region in regions:
                got.append((int(frame), int(region.id), int(region.pairs), float(region.curve_length)))
            assert len(curves) == sum(len(line["curves"]) for line in lines if line["frame"] == frame)
        assert got == [(line["frame"], line["region"], line["pairs"], line["curve_length"]) for line in lines]
        tracks = rec.region_tracks()
    assert len(tracks) == len({line["region"] for line in lines})
    for track in tracks:
        mine = [line for line in lines if line["region"] == track.id]
        assert track.first_frame == mine[0]["frame"] and track.last_frame == mine[-1]["frame"]
        assert track.max_pairs == max(line["pairs"] for line in mine)
    # The splits and merges check prints (its first 20 regions) are the tracks'.
    for match in re.finditer(r"region (\d+): .*?frames (\d+)-(\d+).*?(; split from region (\d+))?(; merged into region (\d+))?\n",
                             err):
        track = tracks[tracks.id == int(match.group(1))][0]
        assert (track.first_frame, track.last_frame) == (int(match.group(2)), int(match.group(3)))
        assert track.split_from == int(match.group(5) or 0)
        assert track.merged_into == int(match.group(7) or 0)


def test_region_depths_and_inside_areas_and_a_1_5_recording(tmp_path, cli):
    """The demo's torus (closed) goes into the sheet: record --regions holds each region's
    inside areas and depth as `check --regions` prints them; a 1.5 recording (no
    /regions/penetration) reads NaN there, in Python and in `inspect`."""
    import json
    import h5py
    scene = ["--scene", "demo:small", "--frames", "8:14"]
    path = tmp_path / "d.h5"
    code, _, err = run_cli(cli, "record", *scene, "--regions", "-o", str(path), "-q")
    assert code == 0, err
    code, out, err = run_cli(cli, "check", *scene, "--regions", "-", "--exit-zero")
    assert code == 0, err
    lines = [json.loads(line) for line in out.splitlines()]
    assert lines and all(line["depth"] is not None for line in lines)
    with collidescope.open(str(path)) as rec:
        got = [(float(r.inside_area_a), float(r.inside_area_b), float(r.depth))
               for frame in rec.frames for r in rec.regions(frame)]
        tracks = rec.region_tracks()
    want = [(line["inside_area"][0] if line["inside_area"][0] is not None else np.nan,
             line["inside_area"][1] if line["inside_area"][1] is not None else np.nan, line["depth"]) for line in lines]
    np.testing.assert_array_equal(np.array(got), np.array(want))
    assert max(d for _, _, d in got) > 0
    assert np.isclose(tracks.max_depth.max(), max(d for _, _, d in got))
    code, out, err = run_cli(cli, "inspect", str(path))
    assert code == 0 and "deepest" in out, out + err
    # The same file as schema 1.5 wrote it.
    with h5py.File(str(path), "r+") as f:
        del f["regions/penetration"]
        f.attrs["schema_version_minor"] = 5
    with collidescope.open(str(path)) as rec:
        regions = rec.regions(rec.frames[2])
        assert len(regions) and np.isnan(regions.depth).all() and np.isnan(regions.inside_area_a).all()
        assert np.isnan(rec.region_tracks().max_depth).all()
    code, out, err = run_cli(cli, "inspect", str(path))
    assert code == 0 and "deepest" not in out, out + err
    code, out, err = run_cli(cli, "validate", str(path))
    assert code == 0, out + err


def test_regions_absent_is_a_clear_error(tmp_path, cli):
    code, _, err = run_cli(cli, "record", "--scene", "C:small", "--frames", "0:2", "-o", str(tmp_path / "p.h5"), "-q")
    assert code == 0, err
    with collidescope.open(str(tmp_path / "p.h5")) as rec:
        assert not rec.has_regions
        with pytest.raises(ValueError, match="no regions recorded"):
            rec.regions(rec.frames[0])


def test_intervals_equal_check_between_frames(tmp_path, cli):
    """record --between-frames read back: intervals() and interval_contacts(frame) hold what
    `check --between-frames` wrote for the same frames (pairs, pass-through flags, toi within the
    printed digits, counts)."""
    import json
    scene = ["--scene", "demo", "--frames", "17:23"]
    code, _, err = run_cli(cli, "record", *scene, "--between-frames", "-o", str(tmp_path / "r.h5"), "-q")
    assert code == 0, err
    code, _, err = run_cli(cli, "check", *scene, "--between-frames", "--exit-zero", "-q",
                           "--pairs", str(tmp_path / "p.tsv"), "--stats", str(tmp_path / "s.jsonl"))
    assert code == 0, err
    rows = [line.split("\t") for line in (tmp_path / "p.tsv").read_text().splitlines() if line and line[0].isdigit()]
    stats = [json.loads(line) for line in (tmp_path / "s.jsonl").read_text().splitlines()]
    with collidescope.open(str(tmp_path / "r.h5")) as rec:
        assert rec.has_intervals
        intervals = rec.intervals()
        assert list(intervals.from_frame) == list(range(17, 22)) and list(intervals.to_frame) == list(range(18, 23))
        assert len(intervals) == len(stats) == 5
        for interval, line in zip(intervals, stats):
            assert [int(interval.from_frame), int(interval.to_frame)] == line["interval"]
            for name, value in line["counts"].items():
                assert int(interval[name]) == value, name
        got = []
        for frame in intervals.from_frame:
            for c in rec.interval_contacts(frame):
                got.append((int(frame), int(c.obj_a), int(c.tri_a), int(c.obj_b), int(c.tri_b), float(c.toi),
                            bool(c.pass_through)))
        with pytest.raises(IndexError, match="last recorded frame"):
            rec.interval_contacts(22)
    assert intervals.pass_throughs.sum() > 0
    assert len(got) == len(rows)
    for mine, theirs in zip(got, rows):
        assert mine[:5] == tuple(int(v) for v in theirs[:5])
        assert mine[6] == (theirs[6] == "1")
        assert 0 <= mine[5] - float(theirs[5]) < 2e-9  # check prints toi rounded down to 9 digits


def test_intervals_absent_is_a_clear_error(tmp_path, cli):
    code, _, err = run_cli(cli, "record", "--scene", "C:small", "--frames", "0:2", "-o", str(tmp_path / "p.h5"), "-q")
    assert code == 0, err
    with collidescope.open(str(tmp_path / "p.h5")) as rec:
        assert not rec.has_intervals
        with pytest.raises(ValueError, match="no intervals recorded"):
            rec.intervals()

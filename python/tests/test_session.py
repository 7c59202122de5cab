"""collidescope.Session: pairs equal `collidescope check --pairs` on every built-in data set,
whatever the dtype and layout of the positions; stats carry check --stats' names; the GIL is
released while the engine runs."""
import json
import os
import threading
import time

import numpy as np
import pytest

import collidescope
import collidescope._core
from conftest import check_pairs, run_cli, session_pairs

DATA_SETS = ["A:small", "B:small", "C:small", "D:small", "E1:small", "E2:small", "E3:small", "E4:small", "demo:small"]


def test_the_package_is_the_built_one():
    """The compiled core loads from the same package directory as the Python files."""
    assert os.path.dirname(collidescope._core.__file__) == os.path.dirname(collidescope.__file__)


@pytest.mark.parametrize("spec", DATA_SETS)
def test_pairs_equal_check(cli, spec):
    scene = collidescope.scene(spec)
    session = collidescope.Session(scene.triangles(), self_collision=scene.self_collision)
    ours = session_pairs(session, scene)
    expected = check_pairs(cli, spec)
    assert len(expected) > 0, "a data set without collisions tests nothing"
    assert ours.shape == expected.shape
    assert np.array_equal(ours, expected)


@pytest.mark.parametrize("method", ["brute", "aabb", "hybrid"])
def test_every_method_gives_the_same_pairs(cli, method):
    scene = collidescope.scene("B:small")
    session = collidescope.Session(scene.triangles(), self_collision=True, method=method, threads=1)
    assert np.array_equal(session_pairs(session, scene), check_pairs(cli, "B:small", "--method", method))


def layouts(positions):
    """The same float32-rounded coordinates in several dtypes and memory layouts."""
    single = positions.astype(np.float32)
    padded = np.zeros((len(positions), 4), dtype=np.float64)
    padded[:, :3] = single
    reversed_rows = np.ascontiguousarray(single[::-1].astype(np.float64))[::-1]
    return {
        "float32": single,
        "float64": single.astype(np.float64),
        "fortran": np.asfortranarray(single.astype(np.float64)),
        "padded rows": padded[:, :3],
        "reversed rows": reversed_rows,
        "list": single.astype(np.float64).tolist(),
    }


def test_every_layout_gives_the_same_pairs():
    scene = collidescope.scene("C:small")
    names = list(layouts(scene.positions(0)[0]))
    sessions = {name: collidescope.Session(scene.triangles(), method="aabb") for name in names}
    total = 0
    for frame in range(len(scene)):
        per_object = [layouts(p) for p in scene.positions(frame)]
        results = {name: s.step([objects[name] for objects in per_object]) for name, s in sessions.items()}
        for name in names:
            assert np.array_equal(results[name], results["float64"]), "%s differs at frame %d" % (name, frame)
        total += len(results["float64"])
    assert total > 0
    assert not per_object[0]["padded rows"].flags.c_contiguous  # the strided path was taken


def test_stats_have_the_names_of_check_stats(cli, tmp_path):
    scene = collidescope.scene("C:small")
    session = collidescope.Session(scene.triangles(), method="adaptive")
    assert session.stats is None
    for frame in range(4):
        pairs = session.step(scene.positions(frame))
    code, out, err = run_cli(cli, "check", "--scene", "C:small", "--frames", "0:4", "--stats", "-", "--exit-zero", "-q")
    assert code == 0, err
    expected = json.loads(out.splitlines()[-1])
    stats = session.stats
    assert list(stats) == list(expected)
    assert list(stats["ms"]) == list(expected["ms"])
    assert list(stats["counts"]) == list(expected["counts"])
    assert stats["frame"] == 3 and session.frame == 4
    assert stats["counts"]["colliding_pairs"] == len(pairs) == expected["counts"]["colliding_pairs"]
    assert stats["decision"]["mode"] in (1, 2)


def test_the_gil_is_released_during_step():
    """A Python thread keeps running while step() runs: its iterations span most of the step
    (without the release they could only fall in the few ms after it returns)."""
    # C's large preset: its first step builds the trees and tests the frame, some 100 ms on a
    # 2-core machine (the default preset's first step took 18 ms there by 2026-11-27, too short
    # to tell a thread that ran beside it from one that ran after it).
    scene = collidescope.scene("C:large")
    session = collidescope.Session(scene.triangles(), method="aabb", threads=1)
    positions = scene.positions(8)
    ticks = []
    done = threading.Event()

    def spin():
        while not done.is_set():
            ticks.append(time.perf_counter())

    worker = threading.Thread(target=spin)
    worker.start()
    try:
        time.sleep(0.01)
        t0 = time.perf_counter()
        session.step(positions)
        t1 = time.perf_counter()
    finally:
        done.set()
        worker.join()
    during = [t for t in ticks if t0 < t < t1]
    assert t1 - t0 > 0.02, "the step is too short to tell (%.1f ms)" % ((t1 - t0) * 1e3)
    assert during and during[-1] - during[0] > 0.5 * (t1 - t0)


def test_with_finishes_the_recording(tmp_path):
    scene = collidescope.scene("demo:small")
    path = str(tmp_path / "run.h5")
    with collidescope.Session(scene.triangles(), method="aabb", record=path) as session:
        session.step(scene.positions(0))
    with collidescope.open(path) as rec:
        assert rec.finished and len(rec) == 1
    with pytest.raises(RuntimeError, match="closed"):
        session.step(scene.positions(1))


def test_the_options_in_the_issue_s_order():
    """Session(triangles, self_collision, method, threads, record), positionally too."""
    scene = collidescope.scene("B:small")
    by_position = collidescope.Session(scene.triangles(), True, "aabb", 1, None)
    by_name = collidescope.Session(scene.triangles(), self_collision=True, method="aabb", threads=1, record=None)
    assert by_position.method == "aabb"
    positions = scene.positions(13)  # the cloths fold onto themselves from frame 11 on
    pairs = by_position.step(positions)
    assert len(pairs) > 0 and np.array_equal(pairs, by_name.step(positions))
    assert (pairs[:, 0] == pairs[:, 2]).any()  # self-collision pairs are there



def test_session_regions_equal_check_regions(cli):
    """Session(regions=True).regions() after each step holds what `check --regions` writes."""
    import json
    from conftest import run_cli
    scene = collidescope.scene("C:small")
    session = collidescope.Session(scene.triangles(), method="aabb", regions=True)
    got = []
    for frame in range(len(scene)):
        session.step(scene.positions(frame))
        for region in session.regions():
            assert all(points.shape[1] == 3 for _, points in region["curves"])
            got.append((frame, region["id"], region["pairs"], region["curve_length"], len(region["curves"]),
                        list(region["predecessors"])))
    code, out, err = run_cli(cli, "check", "--scene", "C:small", "--method", "aabb", "--regions", "-", "--exit-zero", "-q")
    assert code == 0, err
    lines = [json.loads(line) for line in out.splitlines()]
    assert lines, "C:small has regions"
    assert got == [(l["frame"], l["region"], l["pairs"], l["curve_length"], len(l["curves"]), l["predecessors"])
                   for l in lines]
    assert collidescope.Session(scene.triangles()).regions() == []

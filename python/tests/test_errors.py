"""Bad input raises ValueError naming the object and element; engine errors keep the engine's
one-line message (the one `collidescope check` prints)."""
import numpy as np
import pytest

import collidescope
from conftest import run_cli

SQUARE = np.array([[0, 1, 2], [0, 2, 3]])


def square(z, dtype=np.float64):
    return np.array([[0, 0, z], [1, 0, z], [1, 1, z], [0, 1, z]], dtype=dtype)


@pytest.fixture
def session():
    return collidescope.Session([SQUARE, SQUARE], method="brute", names=["floor", "lid"])


def test_positions_dtype(session):
    with pytest.raises(ValueError, match=r"^object 1 \('lid'\): positions of dtype int64, expected float32 or float64$"):
        session.step([square(0), square(1).astype(np.int64)])


def test_positions_shape(session):
    with pytest.raises(ValueError, match=r"^object 0 \('floor'\): positions of shape \(4, 2\), expected \(V, 3\)$"):
        session.step([square(0)[:, :2], square(1)])
    with pytest.raises(ValueError, match=r"^object 0 \('floor'\): positions of shape \(12,\), expected \(V, 3\)$"):
        session.step([square(0).ravel(), square(1)])


def test_object_count(session):
    with pytest.raises(ValueError, match=r"^step: positions for 1 objects, 2 declared$"):
        session.step([square(0)])


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_non_finite_coordinates(session, bad, dtype):
    lid = square(1, dtype)
    lid[2, 1] = bad
    with pytest.raises(ValueError, match=r"^object 1 \('lid'\): vertex 2 has a non-finite y coordinate \((-?inf|nan)\)$"):
        session.step([square(0), lid])
    assert len(session.step([square(0), square(0)])) == 4  # still usable afterwards


def test_index_past_the_vertices(session):
    with pytest.raises(ValueError, match=r"^object 0 \('floor'\): triangle 1 corner 2 is vertex 3, past its 3 vertices$"):
        session.step([square(0)[:3], square(1)])


def test_vertex_count_changes(session):
    session.step([square(0), square(1)])
    with pytest.raises(ValueError, match=r"^object 1 \('lid'\): 3 vertices in frame 1, 4 since frame 0 \(set_triangles"):
        session.step([square(0), square(1)[:3]])
    session.set_triangles(1, [[0, 1, 2]])
    assert len(session.step([square(0), square(0)[:3]])) == 2
    with pytest.raises(ValueError, match=r"^set_triangles: no object 2 \(2 declared\)$"):
        session.set_triangles(2, SQUARE)


@pytest.mark.parametrize("triangles, message", [
    ([SQUARE, np.array([[0, 1, 2], [0, -2, 3]])], r"^object 1: triangle 1 corner 1 is vertex -2, not in \[0, 2\^32\)$"),
    ([SQUARE, np.array([[0, 1, 2], [0, 2, 2 ** 33]])], r"^object 1: triangle 1 corner 2 is vertex 8589934592, not in \[0, 2\^32\)$"),
    ([SQUARE.astype(np.float64)], r"^object 0: triangles of dtype float64, expected integers$"),
    ([SQUARE[:, :2]], r"^object 0: triangles of shape \(2, 2\), expected \(T, 3\)$"),
    ([np.zeros((0, 3), dtype=np.int32)], r"^object 0: no triangles$"),
])
def test_bad_triangles(triangles, message):
    with pytest.raises(ValueError, match=message):
        collidescope.Session(triangles)


@pytest.mark.parametrize("content", [b"ply\nformat ascii 1.0\nelement vertex 3\nend_header\n0 0\n", b"not a mesh"])
def test_engine_errors_keep_check_s_message(cli, tmp_path, monkeypatch, content):
    """A bad input file: the engine's InputError, as check prints it after its prefix."""
    (tmp_path / "bad.ply").write_bytes(content)
    code, _, err = run_cli(cli, "check", "bad.ply", cwd=tmp_path)
    assert code == 2
    message = err.strip().removeprefix("collidescope: error: ")
    assert message != err.strip() and "bad.ply" in message
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ValueError) as raised:
        collidescope.scene_files(["bad.ply"]).positions(0)
    assert str(raised.value) == message


def test_bad_options_are_value_errors():
    with pytest.raises(ValueError, match=r"^unknown method 'nope' \(known: brute, aabb, .*\)$"):
        collidescope.Session([SQUARE], method="nope")
    with pytest.raises(ValueError, match=r"^unknown policy 'nope' \(known: thesis, cost\)$"):
        collidescope.Session([SQUARE], policy="nope")
    with pytest.raises(ValueError, match=r"^threads must be >= 0, got -1$"):
        collidescope.Session([SQUARE], threads=-1)


def test_an_uncreatable_recording_is_named():
    session = collidescope.Session([SQUARE], record="/nonexistent-directory/run.h5")
    with pytest.raises(ValueError, match="/nonexistent-directory/run.h5"):
        session.step([square(0)])

"""Shared fixtures of the Python module's tests: the built `collidescope` command (for
comparisons with check and record) and the package under test, from the build tree."""
import os
import subprocess

import numpy as np
import pytest

import collidescope

SOURCE_DIR = os.environ.get("COLLIDESCOPE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


@pytest.fixture(scope="session")
def cli():
    """The collidescope binary ctest passes (COLLIDESCOPE_BIN); its absence is an error."""
    path = os.environ.get("COLLIDESCOPE_BIN")
    assert path and os.access(path, os.X_OK), "COLLIDESCOPE_BIN must name the built collidescope (ctest sets it)"
    return path


def run_cli(cli, *args, cwd=None):
    """Runs collidescope with ARGS; returns (exit code, stdout, stderr)."""
    done = subprocess.run([cli, *args], cwd=cwd, capture_output=True, text=True)
    return done.returncode, done.stdout, done.stderr


def check_pairs(cli, scene, *options):
    """`check --scene SCENE --pairs -` as an (N, 5) int64 array: frame objA triA objB triB."""
    code, out, err = run_cli(cli, "check", "--scene", scene, "--pairs", "-", "--exit-zero", "-q", *options)
    assert code == 0, err
    return np.array([line.split("\t") for line in out.splitlines()], dtype=np.int64).reshape(-1, 5)


def session_pairs(session, scene):
    """Steps SESSION through every frame of SCENE (changing triangles where the scene does);
    every frame's pairs with the frame
    prepended, as an (N, 5) int64 array like check_pairs."""
    rows = [np.empty((0, 5), dtype=np.int64)]
    in_force = scene.triangles(0)
    for frame in range(len(scene)):
        triangles = scene.triangles(frame) if frame else in_force
        for obj, (new, old) in enumerate(zip(triangles, in_force)):
            if new.shape != old.shape or not np.array_equal(new, old):
                session.set_triangles(obj, new)  # a topology change (the exploding dragons of E)
        in_force = triangles
        pairs = session.step(scene.positions(frame))
        assert pairs.dtype == np.int64 and pairs.ndim == 2 and pairs.shape[1] == 4
        rows.append(np.hstack([np.full((len(pairs), 1), frame, dtype=np.int64), pairs]))
    return np.vstack(rows)



def pytest_sessionfinish(session, exitstatus):
    """Under CI (CI=true, as .ci/run exports it) a skipped test fails the run: CI installs
    everything, so a skip there means a test that never ran (tests/support/ci.hpp)."""
    if os.environ.get("CI") != "true":
        return
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    skipped = reporter.stats.get("skipped", []) if reporter is not None else []
    if skipped:
        print("\nCI=true: %d skipped test(s) fail the run: %s" % (
            len(skipped), ", ".join(report.nodeid for report in skipped)))
        session.exitstatus = 1

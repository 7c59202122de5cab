"""The embedding tutorial's Python loop (docs/tutorials/embedding-loop.md, the block after
<!-- embed-python-loop -->) runs as written."""
import os
import re
import subprocess
import sys

import collidescope

from conftest import SOURCE_DIR


TUTORIAL = os.path.join("docs", "tutorials", "embedding-loop.md")


def test_the_tutorial_python_loop_runs(tmp_path):
    with open(os.path.join(SOURCE_DIR, TUTORIAL), encoding="utf-8") as tutorial:
        match = re.search(r"<!-- embed-python-loop -->\n```python\n(.*?)```", tutorial.read(), re.S)
    assert match, TUTORIAL + ": no ```python block after <!-- embed-python-loop -->"
    code = match.group(1)
    assert len(code.strip().splitlines()) <= 12
    package_root = os.path.dirname(os.path.dirname(os.path.abspath(collidescope.__file__)))
    env = dict(os.environ, PYTHONPATH=package_root)
    done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith("frame 0: ") and lines[15].startswith("frame 15: ")
    assert lines[16].startswith("16 ['object0', 'object1'] ")  # len(rec), default object names
    assert (tmp_path / "loop.h5").exists()

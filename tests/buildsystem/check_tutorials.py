#!/usr/bin/python3
"""The tutorials run as written: every ```sh and ```python block of docs/tutorials/*.md, in
order, in a fresh folder laid out as the repository root after README command (a) (build/app/
collidescope, build/python, scripts/), with Debian's python3. A block that fails fails the
tutorial, naming the block. The Python blocks of a page run as one session: each block runs
after the page's earlier Python blocks. embedding-loop.md's loops have tests of their own
(tests/examples/embed_cpp.cmake, python/tests/test_embedding_tutorial.py) and its shell block
installs into the home folder, so it is left out here.

    check_tutorials.py COLLIDESCOPE PYTHON_PACKAGE_DIR SOURCE_DIR [TUTORIAL.md ...]
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

SKIP = {"embedding-loop.md"}


def blocks(path):
    text = open(path, encoding="utf-8").read()
    return [(m.group(1), m.group(2)) for m in re.finditer(r"```(sh|python)\n(.*?)```", text, re.S)]


def run_tutorial(path, binary, package, source):
    name = os.path.basename(path)
    work = tempfile.mkdtemp(prefix="collidescope_tutorial_")
    try:
        os.makedirs(os.path.join(work, "build", "app"))
        os.symlink(binary, os.path.join(work, "build", "app", "collidescope"))
        os.symlink(package, os.path.join(work, "build", "python"))
        os.symlink(os.path.join(source, "scripts"), os.path.join(work, "scripts"))
        env = dict(os.environ, PYTHONPATH=os.path.join(work, "build", "python"), MPLBACKEND="Agg",
                   OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", PATH="/usr/bin:/bin")
        env["OMPI_MCA_rmaps_base_oversubscribe"] = "1"
        session = ""  # the page's Python blocks so far
        for index, (kind, code) in enumerate(blocks(path), 1):
            if kind == "python":
                session += code + "\n"
            command = ["/bin/bash", "-e", "-o", "pipefail", "-c", code] if kind == "sh" else ["/usr/bin/python3", "-c", session]
            start = time.monotonic()
            done = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True, timeout=600)
            print("%s block %d (%s): exit %d in %.1f s" % (name, index, kind, done.returncode, time.monotonic() - start))
            if done.returncode != 0:
                print("FAIL %s block %d:\n%s\n--- stdout\n%s\n--- stderr\n%s" % (name, index, code, done.stdout[-3000:],
                                                                               done.stderr[-3000:]), file=sys.stderr)
                return False
        return True
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main():
    binary, package, source = (os.path.abspath(a) for a in sys.argv[1:4])
    tutorials = sys.argv[4:] or sorted(os.path.join(source, "docs", "tutorials", f)
                                       for f in os.listdir(os.path.join(source, "docs", "tutorials")) if f.endswith(".md"))
    failed = [t for t in tutorials if os.path.basename(t) not in SKIP and not run_tutorial(t, binary, package, source)]
    if failed:
        print("tutorials that do not run as written: " + ", ".join(map(os.path.basename, failed)), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

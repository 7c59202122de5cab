#!/usr/bin/python3
"""Every source file of the build is compiled into one target: a file two targets need lives in
a library they both link (the command line's collidescope_cli, the test support library, the
recorder, the replayer). Reads the build's compile_commands.json; a unity build's batch file
(CMakeFiles/TARGET.dir/Unity/unity_N_cxx.cxx) counts as the sources it includes.

Usage: check_sources_compiled_once.py BUILD_DIR
"""
import collections
import json
import pathlib
import re
import sys

UNITY_BATCH = re.compile(r"/Unity/unity_[0-9]+_cxx\.cxx$")
UNITY_INCLUDE = re.compile(r'^#include "(.+)"$', re.M)


def sources(entry: dict) -> list:
    """The sources one compile command compiles: its file, or a unity batch's included files."""
    file = entry["file"]
    if UNITY_BATCH.search(file):
        return UNITY_INCLUDE.findall(pathlib.Path(file).read_text())
    return [file]


def main() -> int:
    build = pathlib.Path(sys.argv[1])
    commands = json.loads((build / "compile_commands.json").read_text())
    counts = collections.Counter(source for entry in commands for source in sources(entry))
    twice = {file: n for file, n in counts.items() if n > 1}
    for file, n in sorted(twice.items()):
        print(f"{file} is compiled {n} times (into {n} targets): put it in a library they link")
    print(f"{len(counts)} sources, {len(commands)} compile commands")
    if sum(counts.values()) < 100:
        print("fewer than 100 sources compiled: is this the whole build?")
        return 1
    return 1 if twice else 0


if __name__ == "__main__":
    sys.exit(main())

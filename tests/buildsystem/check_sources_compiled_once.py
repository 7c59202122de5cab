#!/usr/bin/python3
"""Every source file of the build is compiled into one target: a file two targets need lives in
a library they both link (the command line's collidescope_cli, the test support library, the
recorder, the replayer). Reads the build's compile_commands.json.

Usage: check_sources_compiled_once.py BUILD_DIR
"""
import collections
import json
import pathlib
import sys


def main() -> int:
    build = pathlib.Path(sys.argv[1])
    commands = json.loads((build / "compile_commands.json").read_text())
    counts = collections.Counter(entry["file"] for entry in commands)
    twice = {file: n for file, n in counts.items() if n > 1}
    for file, n in sorted(twice.items()):
        print(f"{file} is compiled {n} times (into {n} targets): put it in a library they link")
    print(f"{len(counts)} sources, {len(commands)} compile commands")
    if len(commands) < 100:
        print("fewer than 100 compile commands: is this the whole build?")
        return 1
    return 1 if twice else 0


if __name__ == "__main__":
    sys.exit(main())

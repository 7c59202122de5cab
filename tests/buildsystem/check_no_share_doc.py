#!/usr/bin/python3
"""The build takes nothing from /usr/share/doc, which Debian's container images strip (dpkg's
path-exclude): no CMake file names it, no compile command reads from it and no object's
dependency file lists a header or source under it. The replayer once compiled Dear ImGui's
OpenGL3 backend from there (now replays/src/imgui_renderer.cpp draws ImGui's output itself).

Usage: check_no_share_doc.py SOURCE_DIR BUILD_DIR
"""
import json
import pathlib
import shlex
import sys

DOC = "/usr/share/doc"


def main() -> int:
    source, build = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    problems = []
    cmake_files = [p for p in source.rglob("*") if p.name == "CMakeLists.txt" or p.suffix == ".cmake"]
    cmake_files = [p for p in cmake_files if build not in p.parents and not p.name.startswith(".")]
    for path in cmake_files:
        for number, line in enumerate(path.read_text().splitlines(), 1):
            if DOC in line.split("#", 1)[0]:
                problems.append(f"{path}:{number}: {line.strip()}")
    commands = json.loads((build / "compile_commands.json").read_text())
    depfiles = 0
    replays_depfiles = 0
    for entry in commands:
        if DOC in entry["command"] or DOC in entry["file"]:
            problems.append(f"compile command of {entry['file']} names {DOC}")
        words = shlex.split(entry["command"])
        if "-o" not in words:
            continue
        depfile = pathlib.Path(entry["directory"]) / (words[words.index("-o") + 1] + ".d")
        if not depfile.exists():
            continue  # not built yet: this test runs after the build, so only stray entries
        depfiles += 1
        replays_depfiles += "/replays/" in entry["file"]
        if DOC in depfile.read_text():
            problems.append(f"{entry['file']} includes a file under {DOC} ({depfile})")
    # The check must have seen the build (a wrong directory would pass vacuously).
    if depfiles == 0 or replays_depfiles == 0 or not cmake_files:
        problems.append(f"no dependency files of the replayer under {build}: is it built?")
    for problem in problems:
        print(problem)
    print(f"{len(cmake_files)} CMake files, {len(commands)} compile commands, {depfiles} dependency files checked")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

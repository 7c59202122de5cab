#!/usr/bin/python3
"""The engine's layers, as docs/explanation/architecture.md draws them, hold in engine/src.

The diagram between the markers `<!-- engine-layers -->` and `<!-- /engine-layers -->` in
docs/explanation/architecture.md lists the folders of engine/src, one layer per line, top layer first.
This check fails when
  - a folder of engine/src is in no layer, or the diagram names a folder that does not exist;
  - a file includes a folder of a higher layer (`#include "methods/..."` from bvh/, say);
  - a file includes a public header (engine/include/collidescope/) that a higher layer
    implements: a header belongs to the lowest folder with a .cpp whose first include it is
    (collidescope/pipeline.hpp to pipeline/, say), so the algorithms cannot reach the pipeline
    through its public header. Headers no .cpp implements (interfaces, options) belong to none.

Usage: check_engine_layers.py SOURCE_DIR
"""

import pathlib
import re
import sys

BEGIN, END = "<!-- engine-layers -->", "<!-- /engine-layers -->"
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def read_layers(architecture: pathlib.Path) -> list[list[str]]:
    """The diagram's layers, top first: each line's leading `name/` words."""
    text = architecture.read_text()
    if BEGIN not in text or END not in text:
        sys.exit(f"{architecture}: no engine layer diagram between {BEGIN} and {END}")
    block = text[text.index(BEGIN) + len(BEGIN):text.index(END)]
    layers = []
    for line in block.splitlines():
        words = line.split()
        folders = []
        for word in words:
            if not word.endswith("/") or word == "engine/src/":
                break
            folders.append(word.rstrip("/"))
        if folders:
            layers.append(folders)
    return layers


def public_header_owners(source: pathlib.Path, files: list[pathlib.Path], src: pathlib.Path,
                         rank: dict[str, int]) -> dict[str, str]:
    """collidescope/X.hpp -> the lowest folder of engine/src with a .cpp that includes it first."""
    public = {f"collidescope/{p.name}" for p in (source / "engine" / "include" / "collidescope").glob("*.hpp")}
    owners: dict[str, str] = {}
    for path in files:
        folder = path.relative_to(src).parts[0]
        includes = INCLUDE.findall(path.read_text())
        if path.suffix != ".cpp" or folder not in rank or not includes or includes[0] not in public:
            continue
        header = includes[0]
        if header not in owners or rank[folder] < rank[owners[header]]:
            owners[header] = folder
    return owners


def main() -> int:
    source = pathlib.Path(sys.argv[1])
    src = source / "engine" / "src"
    layers = read_layers(source / "docs" / "explanation" / "architecture.md")
    rank = {}  # folder -> layer number, 0 = bottom
    for number, folders in enumerate(reversed(layers)):
        for folder in folders:
            if folder in rank:
                print(f"docs/explanation/architecture.md: engine/src/{folder}/ is in two layers")
                return 1
            rank[folder] = number
    problems = []
    on_disk = sorted(p.name for p in src.iterdir() if p.is_dir())
    for folder in on_disk:
        if folder not in rank:
            problems.append(f"engine/src/{folder}/ is in no layer of docs/explanation/architecture.md's diagram")
    for folder in sorted(set(rank) - set(on_disk)):
        problems.append(f"docs/explanation/architecture.md's diagram names engine/src/{folder}/, which does not exist")

    files = sorted(p for p in src.rglob("*") if p.suffix in (".cpp", ".hpp"))
    owners = public_header_owners(source, files, src, rank)
    for path in files:
        folder = path.relative_to(src).parts[0]
        if folder not in rank:
            continue
        for include in INCLUDE.findall(path.read_text()):
            target = include.split("/")[0]
            if target in rank and rank[target] > rank[folder]:
                problems.append(f"{path.relative_to(source)}: includes \"{include}\", a layer above {folder}/")
            owner = owners.get(include)
            if owner is not None and rank[folder] < rank[owner]:
                problems.append(f"{path.relative_to(source)}: includes \"{include}\" (implemented in {owner}/), "
                                f"a layer above {folder}/")
    for problem in problems:
        print(problem)
    if not problems:
        print(f"{len(files)} files in {len(on_disk)} folders keep to {len(layers)} layers")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Every stats name that `collidescope check --stats` prints is listed in
docs/reference/stats.md: each method on a scene where its details are filled (the GPU cull's
passes need a frame with a potentially colliding set). A name is listed when it appears in
backticks, as `group.name`, or for the fields of an array of records (gpu.views[],
gpu.passes[]) as `field` on that array's row.

    check_stats_reference.py COLLIDESCOPE SOURCE_DIR
"""
import json
import re
import subprocess
import sys

RUNS = [("brute", "demo:small"), ("aabb", "C:small"), ("gpu", "C:small"), ("hybrid", "C:small"), ("adaptive", "C:small")]


def names(value, prefix=""):
    """Dotted names of a stats record's leaves; arrays of records as name[].field."""
    if isinstance(value, dict):
        for key, item in value.items():
            yield from names(item, prefix + "." + key if prefix else key)
    elif isinstance(value, list) and value and isinstance(value[0], dict):
        for record in value:
            for key in record:
                yield prefix + "[]." + key
    else:
        yield prefix


def main():
    binary, source = sys.argv[1], sys.argv[2]
    page = open(source + "/docs/reference/stats.md", encoding="utf-8").read()
    listed = set(re.findall(r"`([^`]+)`", page))
    rows = {}
    for line in page.splitlines():  # `gpu.passes[]` | per pass: `level`, ...
        match = re.match(r"\| `([a-z_.]+\[\])` \|(.*)\|", line)
        if match:
            rows[match.group(1)] = set(re.findall(r"`([^`]+)`", match.group(2)))
    seen, missing = set(), []
    for method, scene in RUNS:
        done = subprocess.run([binary, "check", "--scene", scene, "--method", method, "--frames", "0:10",
                               "--stats", "-", "--exit-zero", "-q"], capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit("check --method %s failed: %s" % (method, done.stderr))
        for line in done.stdout.splitlines():
            for name in names(json.loads(line)):
                if name in seen:
                    continue
                seen.add(name)
                array, _, field = name.partition("[].")
                ok = field in rows.get(array + "[]", set()) if field else name in listed
                if not ok:
                    missing.append("%s (from --method %s)" % (name, method))
    for required in ("gpu.passes[].samples_passed", "decision.action", "hybrid.a1", "aabb.tree_quality"):
        if required not in seen:
            missing.append("%s never printed: the runs above no longer reach it" % required)
    if missing:
        print("docs/reference/stats.md does not list:\n  " + "\n  ".join(missing), file=sys.stderr)
        return 1
    print("%d stats names, every one listed in docs/reference/stats.md" % len(seen))
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Runs `collidescope check FILE` on every file of a model corpus (Debian's assimp-testmodels).

Each file must either load (exit 0 or 1: no collisions or collisions) or be refused with exit
2 and exactly one line on stderr, `collidescope: error: FILE: ...`, naming the file; nothing
may crash (a signal) or run past the time limit. Every regular file of the corpus is given,
textures and buffers included: a user may pass any file.

    check_model_corpus.py COLLIDESCOPE [--models DIR] [--shard I/N] [--jobs J] [--timeout S]
                          [--summary]

--shard I/N takes every N-th file from the I-th (sorted paths), so a corpus splits into
ctest entries that run in parallel. --summary prints each file's outcome (TSV) and counts
of the refusals by their reason, the data behind docs/reference/robustness.md.

Which files load is pinned: corpus_loads.txt beside this script lists them (relative paths,
sorted). A listed file that is refused, an unlisted one that loads, or a listed one missing from
the corpus fails the sweep, so a regression that refuses every model cannot pass as a run of
clean refusals. --write-pin rewrites the list from a whole sweep (no --shard), after a change
meant to alter it.

A missing corpus directory is a skip (exit 77) on a developer's machine and a failure under
CI (env CI=true): the package is installed by scripts/setup.sh.
"""

import argparse
import collections
import concurrent.futures
import os
import re
import signal
import subprocess
import sys
import time

SKIP = 77
DEFAULT_MODELS = "/usr/share/assimp/models"
DEFAULT_PIN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus_loads.txt")
PIN_HEADER = """\
# The files of Debian 12's assimp-testmodels (5.2.5) that `collidescope check` loads, relative to
# /usr/share/assimp/models, sorted; the others are refused with one line. check_model_corpus.py fails
# a sweep where a listed file is refused or an unlisted one loads: after a change that should alter
# this, regenerate it with --write-pin (docs/reference/robustness.md) and say why in the commit.
"""


def read_pin(path):
    with open(path, encoding="utf-8") as pin:
        return {line.rstrip("\n") for line in pin if line.strip() and not line.startswith("#")}


def write_pin(path, loaded):
    with open(path, "w", encoding="utf-8") as pin:
        pin.write(PIN_HEADER)
        for name in sorted(loaded, key=lambda n: n.encode("utf-8")):
            pin.write(name + "\n")


def pin_failures(results, all_files, shard_files, pinned, models):
    """(path, kind, detail) for each difference between this shard's outcomes and the pin."""
    failures = []
    for path, outcome, _, detail in results:
        name = os.path.relpath(path, models)
        if name in pinned and outcome == "refused":
            failures.append((path, "was loading", "pinned in corpus_loads.txt, now refused: " + detail))
        elif name not in pinned and outcome == "loaded":
            failures.append((path, "not pinned", "loads but is not in corpus_loads.txt (--write-pin)"))
    # A pinned file the corpus lacks is reported by the shard it would have fallen in: shard 0.
    if shard_files and shard_files[0] == all_files[0]:
        present = {os.path.relpath(path, models) for path in all_files}
        for name in sorted(pinned - present):
            failures.append((os.path.join(models, name), "pinned but missing", "not in the corpus"))
    return failures


def corpus_files(models):
    files = []
    for root, dirs, names in os.walk(models):
        dirs.sort()
        for name in sorted(names):
            path = os.path.join(root, name)
            if os.path.isfile(path) and not os.path.islink(path):
                files.append(path)
    return sorted(files)


def missing_corpus(models):
    """None when the corpus directory exists; else the exit code after saying why: a skip (77)
    on a developer's machine, a failure under CI (env CI=true)."""
    if os.path.isdir(models):
        return None
    message = "%s: no such directory (Debian's assimp-testmodels; scripts/setup.sh installs it)" % models
    if os.environ.get("CI") == "true":
        print("FAIL: CI: " + message, file=sys.stderr)
        return 1
    print("SKIP: " + message, file=sys.stderr)
    return SKIP


def run_one(binary, path, timeout):
    """(path, outcome, seconds, detail): outcome is loaded, refused or a failure's kind."""
    start = time.monotonic()
    try:
        done = subprocess.run([binary, "check", "--quiet", "--exit-zero", path],
                              stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, timeout=timeout)
    except subprocess.TimeoutExpired:
        return path, "hang", time.monotonic() - start, "ran past %g s" % timeout
    seconds = time.monotonic() - start
    err = done.stderr.decode("utf-8", "replace")
    lines = err.splitlines()
    if done.returncode < 0:
        return path, "crash", seconds, "killed by %s" % signal.Signals(-done.returncode).name
    if done.returncode == 0:
        return path, "loaded", seconds, lines[-1] if lines else ""
    if done.returncode != 2:
        return path, "bad exit", seconds, "exit %d: %s" % (done.returncode, err.strip()[:300])
    prefix = "collidescope: error: " + path
    if len(lines) != 1 or not lines[0].startswith(prefix) or not err.endswith("\n"):
        return path, "bad message", seconds, "expected one line starting %r, got %r" % (prefix, err[:500])
    return path, "refused", seconds, lines[0][len(prefix):].lstrip(": ")


def reason_class(message):
    """A refusal's reason without its particulars (numbers, quoted text), for counting."""
    text = re.sub(r"\(object '[^']*'\)$", "", message).strip()
    text = re.sub(r"\(.*", "", text) if text.startswith("assimp cannot read it") else text
    text = re.sub(r"'[^']*'|\"[^\"]*\"", "'…'", text)
    return re.sub(r"\d+", "N", text).strip()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("binary")
    parser.add_argument("--models", default=DEFAULT_MODELS)
    parser.add_argument("--shard", default="0/1")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=10.0)
    parser.add_argument("--summary", action="store_true")
    parser.add_argument("--pin", default=DEFAULT_PIN)
    parser.add_argument("--write-pin", action="store_true")
    args = parser.parse_args()

    missing = missing_corpus(args.models)
    if missing is not None:
        return missing
    index, count = (int(part) for part in args.shard.split("/"))
    if args.write_pin and count != 1:
        print("FAIL: --write-pin needs the whole corpus (no --shard)", file=sys.stderr)
        return 2
    all_files = corpus_files(args.models)
    files = all_files[index::count]
    if not files:
        print("FAIL: no files in %s (shard %s)" % (args.models, args.shard), file=sys.stderr)
        return 1

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(lambda path: run_one(args.binary, path, args.timeout), files))

    failures = [r for r in results if r[1] not in ("loaded", "refused")]
    if args.write_pin:
        write_pin(args.pin, [os.path.relpath(r[0], args.models) for r in results if r[1] == "loaded"])
    else:
        pinned = read_pin(args.pin)
        failures += [(path, kind, 0.0, detail)
                     for path, kind, detail in pin_failures(results, all_files, files, pinned, args.models)]
    outcomes = collections.Counter(r[1] for r in results)
    slowest = max(results, key=lambda r: r[2])
    if args.summary:
        for path, outcome, seconds, detail in results:
            print("%s\t%s\t%.2f\t%s" % (os.path.relpath(path, args.models), outcome, seconds, detail))
        reasons = collections.Counter(reason_class(r[3]) for r in results if r[1] == "refused")
        for reason, n in reasons.most_common():
            print("refused\t%d\t%s" % (n, reason))
    for path, outcome, seconds, detail in failures:
        print("FAIL %s: %s (%.1f s): %s" % (path, outcome, seconds, detail), file=sys.stderr)
    print("%d files (shard %s of %s): %s; slowest %.2f s (%s)" % (
        len(results), args.shard, args.models,
        ", ".join("%d %s" % (n, k) for k, n in sorted(outcomes.items())),
        slowest[2], os.path.relpath(slowest[0], args.models)), file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

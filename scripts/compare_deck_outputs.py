#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Runs the deck-level tests of two builds and compares every file they write, byte for byte.

For a restructure that must keep every output: build the commit before and the commit after
(each from its own checkout), then

    scripts/compare_deck_outputs.py --base BUILD_BEFORE --new BUILD_AFTER --work DIR

runs each deck test of both builds alone (`ctest -R ^NAME$`) with its temporary folders kept
under DIR/{base,new}/NAME (the tests make them with Python's tempfile, which this script keeps
through a sitecustomize module), then compares the files: byte for byte, after replacing each
build's own paths (work folder, build folder, source folder, the random part of temporary
names) by placeholders. Log files are compared on their thermo rows and summary lines only
(their timings differ from run to run). Prints one line per test and exits 1 on a difference.
"""
import argparse
import concurrent.futures
import os
import re
import subprocess
import sys

DEFAULT_LABELS = "deck|validation|defect|sweep|signal|catalog|mpi|output"
# Outputs that differ between two runs of the same build: a signal sent at a wall-clock time
# (run_status_interrupted), the start time of a sweep (t0), which partition ran which case
# (the universe log and screens of a partitioned sweep).
VOLATILE_TESTS = {"run_status_interrupted"}
VOLATILE_FILES = re.compile(r"^(t0|screen\.\d+|log\.liggghts)$")
KEEP = '''
import tempfile, weakref
_Orig = tempfile.TemporaryDirectory
class _Kept(_Orig):
    def __init__(self, *a, **k):
        super().__init__(*a, **k)
        self._finalizer.detach()
    def cleanup(self):
        pass
    def __exit__(self, *a):
        pass
tempfile.TemporaryDirectory = _Kept
'''


def cache_value(build, key):
    with open(os.path.join(build, "CMakeCache.txt")) as f:
        for line in f:
            if line.startswith(key + ":"):
                return line.split("=", 1)[1].strip()
    sys.exit(f"ERROR: {build}/CMakeCache.txt has no {key}")


def test_names(build, labels):
    out = subprocess.run(["ctest", "--test-dir", build, "-N", "-L", labels],
                         capture_output=True, text=True, check=True).stdout
    return [m.group(1) for m in re.finditer(r"Test\s+#\d+: (\S+)", out)]


def run_one(build, name, root, keep_dir):
    wd = os.path.join(root, name)
    os.makedirs(wd, exist_ok=True)
    env = dict(os.environ, TMPDIR=wd, PYTHONPATH=keep_dir)
    res = subprocess.run(["ctest", "--test-dir", build, "-R", f"^{re.escape(name)}$"],
                         capture_output=True, text=True, env=env)
    return name, res.returncode


def normalise(text, build, src, root):
    for path, tag in ((root, "<WORK>"), (build, "<BUILD>"), (src, "<SRC>")):
        text = text.replace(os.path.realpath(path), tag).replace(path, tag)
    # tempfile names: a prefix, then 8 random characters of [a-z0-9_]
    return re.sub(r"(<WORK>/[^/\s\"']*?)[a-z0-9_]{8}(?=[/\s\"']|$)", r"\1XXXXXXXX", text)


NUMBER = re.compile(r"^[-+]?(\d+\.?\d*([eE][-+]?\d+)?|\.\d+([eE][-+]?\d+)?|inf|nan|-nan)$")


def log_rows(text):
    """Thermo rows (less the columns of CPU time) and summary lines of a LIGGGHTS log."""
    keep, timed = [], []
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("Step"):
            timed = [i for i, w in enumerate(s.split()) if w.lower().startswith("cpu")]
        elif s.startswith(("BEARING_SUMMARY", "ERROR", "WARNING")):
            # where in our source a message is raised moves with the code: the text is compared
            keep.append(re.sub(r"\(<SRC>/[^()]+:\d+\)$", "(<SRC>)", s))
        elif all(NUMBER.match(w) for w in s.split()) and s:
            keep.append(" ".join(w for i, w in enumerate(s.split()) if i not in timed))
    return "\n".join(keep)


def files_of(root, name, build, src):
    table = {}
    top = os.path.join(root, name)
    for d, _, fs in os.walk(top):
        for f in fs:
            if VOLATILE_FILES.match(f):
                continue
            p = os.path.join(d, f)
            rel = normalise(p, build, src, os.path.join(root, name))
            table.setdefault(rel, []).append(p)
    return table


def content(path, build, src, root):
    with open(path, "rb") as f:
        data = f.read()
    text = normalise(data.decode(errors="surrogateescape"), build, src, root)
    base = os.path.basename(path)
    if base.startswith(("log", "screen")) or base.endswith((".log", ".out", ".err")):
        text = log_rows(text)
    elif base.endswith(".raw"):  # ngspice's output states the date
        text = re.sub(r"(?m)^Date:.*$", "Date:", text)
    elif base == "finished.txt":  # partitions finish their cases in any order
        text = "\n".join(sorted(text.splitlines()))
    return text.encode(errors="surrogateescape")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--base", required=True, help="build folder of the commit before")
    ap.add_argument("--new", required=True, help="build folder of the commit after")
    ap.add_argument("--work", required=True, help="folder for the kept outputs")
    ap.add_argument("--labels", default=DEFAULT_LABELS, help="ctest label regex")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", nargs="*", help="test names (default: all with the labels)")
    ap.add_argument("--gone", nargs="*", default=[],
                    help="file names the new build no longer writes by design (counted apart)")
    ap.add_argument("--compare-only", action="store_true",
                    help="compare the outputs kept in --work by an earlier call, run nothing")
    a = ap.parse_args()
    keep_dir = os.path.join(a.work, "keep")
    os.makedirs(keep_dir, exist_ok=True)
    with open(os.path.join(keep_dir, "sitecustomize.py"), "w") as f:
        f.write(KEEP)
    builds = {"base": os.path.realpath(a.base), "new": os.path.realpath(a.new)}
    srcs = {k: cache_value(b, "CMAKE_HOME_DIRECTORY") for k, b in builds.items()}
    names = a.only or sorted((set(test_names(builds["base"], a.labels))
                              & set(test_names(builds["new"], a.labels))) - VOLATILE_TESTS)
    status = {}
    if a.compare_only:
        names = [n for n in names if os.path.isdir(os.path.join(a.work, "base", n))]
    else:
        with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
            jobs = [pool.submit(run_one, builds[k], n, os.path.join(a.work, k), keep_dir)
                    for k in builds for n in names]
            for j in concurrent.futures.as_completed(jobs):
                n, rc = j.result()
                status.setdefault(n, []).append(rc)
    bad = 0
    for n in names:
        roots = {k: os.path.join(os.path.realpath(a.work), k) for k in builds}
        tabs = {k: files_of(roots[k], n, builds[k], srcs[k]) for k in builds}
        keys = sorted(set(tabs["base"]) | set(tabs["new"]))
        diffs, same, gone = [], 0, 0
        for key in keys:
            pa, pb = tabs["base"].get(key, []), tabs["new"].get(key, [])
            if not pb and os.path.basename(key) in a.gone:
                gone += len(pa)
                continue
            if len(pa) != len(pb):
                diffs.append(f"only in {'base' if len(pa) > len(pb) else 'new'}: {key}")
                continue
            for x, y in zip(sorted(pa), sorted(pb)):
                cx = content(x, builds["base"], srcs["base"], os.path.join(roots["base"], n))
                cy = content(y, builds["new"], srcs["new"], os.path.join(roots["new"], n))
                if cx == cy:
                    same += 1
                else:
                    diffs.append(f"differs: {key}")
        rc = ("not run" if n not in status else
              "pass" if all(r == 0 for r in status[n]) else f"exit {status[n]}")
        gone_note = f", {gone} gone by design" if gone else ""
        print(f"{n}: {same} files identical, {len(diffs)} differences{gone_note} (tests: {rc})")
        for d in diffs:
            print("   ", d)
        bad += bool(diffs)
    print(f"{len(names)} tests compared, {bad} with differences")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())

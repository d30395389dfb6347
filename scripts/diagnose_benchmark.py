#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Scores `ohmdem-post diagnose` on a folder of records with a truth table.

    diagnose_benchmark.py --exe build/ohmdem-post --root DIR TRUTH.csv [TRUTH.csv ...]

TRUTH.csv: a header `file,truth,args`, then one row per record: the file (relative to --root),
its truth (none for a healthy bearing, inner, outer, ball, cage, or fault when only the presence
of a fault is known) and the diagnose options for it (rate, speed, bearing, variable), separated
by spaces. Prints each verdict, the confusion matrix (truth x verdict) and the false-alarm rate:
healthy records named after a family (inner, outer, ball, cage; cage?ball is a cage verdict
with a possible ball defect) over the healthy records; the
healthy records merely flagged (unidentified: a detection test fired; ambiguous) are counted
apart, and so are those whose impulses are the other bearing's (other-bearing: diagnose
--other-bearing, the healthy fan-end channel of a drive-end fault). Exit status 0;
--require-no-false-alarm, --require-races-right and --max-healthy-flagged N turn the goals
into an exit status (1 when missed).
"""
import argparse
import csv
import json
import os
import shlex
import subprocess
import sys

VERDICTS = ["none", "inner", "outer", "ball", "cage", "cage?ball", "ambiguous", "unidentified",
            "other-bearing"]
FAMILIES = {"inner", "outer", "ball", "cage", "cage?ball"}


def diagnose(exe, path, args):
    out = subprocess.run([exe, "diagnose", path, *shlex.split(args), "--no-size", "--format",
                          "json"], capture_output=True, text=True)
    if out.returncode != 0:
        return "error", 0.0, out.stderr.strip()
    j = json.loads(out.stdout)
    note = j.get("candidate", "")
    if j["defect"] == "other-bearing":  # candidate: the other bearing's family
        return "other-bearing", j["score"], "the other bearing's " + j["fundamental"]
    verdict = j["defect"]
    if verdict == "cage" and note == "ball":
        verdict = "cage?ball"  # cage (possible ball defect)
    return verdict, j["score"], ("candidate " + note) if note else ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", required=True, help="the ohmdem-post executable")
    ap.add_argument("--root", default=".", help="folder the truth tables' files are relative to")
    ap.add_argument("--require-no-false-alarm", action="store_true")
    ap.add_argument("--require-races-right", action="store_true")
    ap.add_argument("--max-healthy-flagged", type=int, default=None, metavar="N",
                    help="fail when more than N healthy records are unidentified or ambiguous")
    ap.add_argument("truth", nargs="+", help="truth tables (CSV: file,truth,args)")
    a = ap.parse_args()
    rows = []
    for table in a.truth:
        with open(table, newline="") as f:
            for r in csv.DictReader(f):
                rows.append(r)
    matrix = {}
    healthy = alarms = flagged = other = races = races_right = 0
    print(f"{'file':<44} {'truth':<7} {'verdict':<13} score")
    for r in rows:
        verdict, score, note = diagnose(a.exe, os.path.join(a.root, r["file"]), r["args"])
        truth = r["truth"]
        print(f"{r['file']:<44} {truth:<7} {verdict:<13} {score:.2f} {note}")
        matrix.setdefault(truth, {}).setdefault(verdict, 0)
        matrix[truth][verdict] += 1
        if truth == "none":
            healthy += 1
            alarms += verdict in FAMILIES
            flagged += verdict in ("unidentified", "ambiguous")
            other += verdict == "other-bearing"
        if truth in ("inner", "outer"):
            races += 1
            races_right += verdict == truth
    cols = VERDICTS + sorted({v for t in matrix.values() for v in t} - set(VERDICTS))
    print("\nconfusion matrix (rows: truth, columns: verdict)")
    print(f"{'':<8}" + "".join(f"{c:>14}" for c in cols))
    for t in sorted(matrix):
        print(f"{t:<8}" + "".join(f"{matrix[t].get(c, 0):>14}" for c in cols))
    if healthy:
        print(f"\nfalse alarms (healthy named after a family): {alarms} of {healthy} "
              f"({100.0 * alarms / healthy:.1f} %); healthy flagged unidentified/ambiguous: "
              f"{flagged} of {healthy}; healthy whose impulses are the other bearing's: "
              f"{other} of {healthy}")
    if races:
        print(f"inner and outer records right: {races_right} of {races}")
    failed = (a.require_no_false_alarm and alarms > 0) or \
             (a.require_races_right and races_right < races) or \
             (a.max_healthy_flagged is not None and flagged > a.max_healthy_flagged)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

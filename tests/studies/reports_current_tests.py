#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The committed reports still hold: a quick report made again at this commit, its tables
compared with the committed one's (the tables only: dates, commits and costs differ).
  detectability: studies/detectability.py --quick OUT against doc/report/detectability/
                 detectability.md (every table line, in order)
  protocol:      the first 30 cases of doc/report/protocol/protocol.csv's seed run again
                 (studies/protocol.py --n 30 --seed S: case i is the same for every N) and their
                 answers (diagnosis, size, interval, place) compared with the committed rows
A difference fails the test with the lines that differ: the code changed what the report says,
and the report must be made again (its command is in its first lines).
Usage: reports_current_tests.py detectability|protocol --src SOURCE_DIR --out FOLDER"""
import argparse
import csv
import os
import re
import subprocess
import sys

PROTOCOL_CASES = 30
ANSWER = ("key", "diagnosis", "size_est_deg", "size_low_deg", "size_high_deg",
          "position_est_deg", "position_reference")


def tables(text):
    return [l.rstrip() for l in text.splitlines() if l.startswith("|")]


def differences(committed, now, what):
    out = []
    for i in range(max(len(committed), len(now))):
        c = committed[i] if i < len(committed) else "(none)"
        n = now[i] if i < len(now) else "(none)"
        if c != n:
            out.append(f"{what} {i + 1}:\n    committed: {c}\n    now:       {n}")
    return out


def study(src, args):
    r = subprocess.run(["/usr/bin/python3", os.path.join(src, "studies", args[0])] + args[1:],
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAIL {' '.join(args)}: exit {r.returncode}: {r.stderr[-1500:]}")


def detectability(src, out):
    committed = os.path.join(src, "doc", "report", "detectability", "detectability.md")
    study(src, ["detectability.py", "--quick", "--jobs", "2", out])
    with open(committed) as f, open(os.path.join(out, "detectability.md")) as g:
        return differences(tables(f.read()), tables(g.read()), "table line")


def protocol(src, out):
    folder = os.path.join(src, "doc", "report", "protocol")
    with open(os.path.join(folder, "protocol.md")) as f:
        m = re.search(r"\bcases, seed (\d+)\.", f.read())
    if not m:
        sys.exit("FAIL doc/report/protocol/protocol.md states no seed ('N cases, seed S.')")
    with open(os.path.join(folder, "protocol.csv")) as f:
        committed = list(csv.DictReader(f))[:PROTOCOL_CASES]
    study(src, ["protocol.py", "--n", str(PROTOCOL_CASES), "--seed", m.group(1), "--jobs", "2",
                out])
    with open(os.path.join(out, "protocol.csv")) as f:
        now = list(csv.DictReader(f))
    row = lambda r: "case " + r["case"] + ": " + ", ".join(f"{k}={r[k]}" for k in ANSWER)
    return differences([row(r) for r in committed], [row(r) for r in now], "row")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("report", choices=("detectability", "protocol"))
    p.add_argument("--src", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    diff = (detectability if a.report == "detectability" else protocol)(a.src, a.out)
    if diff:
        print("\n".join(diff))
        sys.exit(f"FAIL the committed {a.report} report no longer holds: {len(diff)} "
                 "difference(s) above; make it again with the command its first lines state")
    print(f"ok   the committed {a.report} report's tables are what this commit makes")


if __name__ == "__main__":
    main()

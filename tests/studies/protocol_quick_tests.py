#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The validation protocol's smoke version (studies/protocol.py --quick): 30 cases of its fixed
seed simulated, acquired and diagnosed. Fails when the study breaks: a case that cannot be run,
recorded or diagnosed (the study's own exit status), a record that is not the drawn chain (its
header's rate, noise density and seed against the case), a user's run.json that still names the
defect, a report without its tables or the estimator's hash, a rerun from the cache that does
not give the same rows. One floor on the numbers: the kind accuracy's 95 % interval must reach
chance (1/4, four kinds drawn alike); an estimator below it answers worse than a coin.
Usage: protocol_quick_tests.py --src SOURCE_DIR --out FOLDER (kept: the case cache)"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys

failed = []


def check(cond, msg):
    print(("ok   " if cond else "FAIL ") + msg)
    if not cond:
        failed.append(msg)


def run(src, out):
    return subprocess.run(["/usr/bin/python3", os.path.join(src, "studies", "protocol.py"),
                           "--quick", "--jobs", "2", out], capture_output=True, text=True)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--src", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    sys.path.insert(0, os.path.join(a.src, "studies"))
    import protocol
    r = run(a.src, a.out)
    check(r.returncode == 0, "protocol.py --quick runs: " + r.stderr[-1500:])
    if r.returncode != 0:
        sys.exit(1)
    with open(os.path.join(a.out, "protocol.csv")) as f:
        rows = list(csv.DictReader(f))
    cases = protocol.draw(protocol.QUICK_SEED, protocol.QUICK_N)
    check(len(rows) == len(cases) == 30, f"30 rows, got {len(rows)}")
    answers = {"none", "inner", "outer", "ball", "cage", "ambiguous", "unidentified",
               "other-bearing"}
    for c, row in zip(cases, rows):
        check(row["key"] == protocol.key(c) and row["diagnosis"] in answers,
              f"case {c['index']}: {c['bearing']} {c['kind']} {c['load']} {c['rate_hz']:g} Hz "
              f"-> {row['diagnosis']}")
        folder = os.path.join(a.out, "cases", row["key"])
        with open(os.path.join(folder, "run.json")) as f:
            meta = json.load(f)
        left = [k for k in protocol.TRUTH_KEYS if k in meta]
        check(not left and meta.get("bearing") == c["bearing"],
              f"case {c['index']}: the user's run.json names the bearing, not the defect {left}")
        with open(os.path.join(folder, "record.txt")) as f:
            head = "".join(l for l in f if l.startswith("#"))
        rate = re.search(r"^# sampling rate \(Hz\): (\S+)$", head, re.M)
        noise = re.search(r"density (\S+) per sqrt\(Hz\).*seed (\d+)", head)
        check(rate and float(rate.group(1)) == c["rate_hz"] and noise and
              float(noise.group(1)) == protocol.SPACE["noise"][c["noise"]] and
              int(noise.group(2)) == c["noise_seed"] and "# time V angle_inner" in head and
              ("clipped 0 of" in head) != bool(row["note"]),
              f"case {c['index']}: the record is the drawn chain (rate, noise, seed; clipped "
              "only where the simulation's circuit opened)")
    with open(os.path.join(a.out, "protocol.md")) as f:
        md = f.read()
    est = protocol.estimator()
    check(est["hash"] in md and "Regenerated at commit" in md and "seed 1" in md,
          "the report states the estimator's hash, the commit and the seed")
    for title in ("All cases", "Per defect kind", "Per bearing", "Per load mode",
                  "Per acquisition rate", "Per noise level", "Confusion"):
        check(f"### {title}" in md, f"the report's table '{title}'")
    right = sum(r["kind_right"] == "True" for r in rows)
    lo, hi = protocol.wilson(right, len(rows))
    check(hi >= 0.25, f"kind right {right}/{len(rows)}, 95 % interval [{lo:.2f}, {hi:.2f}] reaches "
          "chance (0.25)")
    first = open(os.path.join(a.out, "protocol.csv")).read()
    r = run(a.src, a.out)
    check(r.returncode == 0 and "0 simulated, 30 from the cache" in open(
        os.path.join(a.out, "protocol.md")).read(), "a rerun takes every case from the cache")
    check(open(os.path.join(a.out, "protocol.csv")).read() == first,
          "the rerun writes the same rows")
    if failed:
        sys.exit(f"{len(failed)} check(s) failed")
    print("all checks passed")


if __name__ == "__main__":
    main()

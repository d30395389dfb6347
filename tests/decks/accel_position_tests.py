#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""An inner pit's place from the accelerometer (studies/accel_position.py --tiny, issue 26): one
0.35 s run (a 1 deg inner pit at 135 deg on the ring, radial load) acquired by the accelerometer
at 20 kHz with the deck's shaft angle, sized on the committed curve and placed by diagnose
--size-method accel-curve. Checks the files, the place within the issue's 10 deg, and that the
interval holds it.
Usage: accel_position_tests.py --exe OHMDEM --post OHMDEM_POST --src SOURCE_DIR"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

from deck_checks import check, finish


def main():
    p = argparse.ArgumentParser()
    for name in ("--exe", "--post", "--src"):  # ohmdem, ohmdem-post, the source tree
        p.add_argument(name, required=True)
    a = p.parse_args()
    with tempfile.TemporaryDirectory() as out:
        env = dict(os.environ, OHMDEM=a.exe, POST=a.post)
        r = subprocess.run(["/usr/bin/python3", os.path.join(a.src, "studies",
                                                             "accel_position.py"), "--tiny", out],
                           env=env, capture_output=True, text=True)
        check(r.returncode == 0, "accel_position.py --tiny runs: " + r.stderr[-400:])
        with open(os.path.join(out, "accel_position.csv")) as f:
            rows = list(csv.DictReader(f))
        check(len(rows) == 1, f"one row, got {len(rows)}")
        row = rows[0]
        check(row["error_deg"] != "" and abs(float(row["error_deg"])) <= 10,
              f"placed within 10 deg of 135: {row}")
        check(row["covers"] == "True", f"the interval holds the place: {row}")
        check(row["size_est_deg"] != "" and abs(float(row["size_est_deg"]) - 1) < 0.15,
              f"sized within 15 % on the committed curve: {row}")
        with open(os.path.join(out, "accel_position.md")) as f:
            md = f.read()
        check("| low | 1/1," in md and "20 kHz" in md, "the table names the case and the rate")
    finish()


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""An outer pit's angle from a two-axis accelerometer (studies/accel_outer_angle.py
--tiny): one 0.35 s run (a 1 deg outer pit 25 deg from the load direction, radial load), both
ring axes acquired at 20 kHz into one record and placed by diagnose --size-method accel-curve
--across-column V2. Checks the files, the angle within the goal's 15 deg (the study: within
3 deg), and that the interval holds it.
Usage: accel_outer_angle_tests.py --exe OHMDEM --post OHMDEM_POST --src SOURCE_DIR"""
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
                                                             "accel_outer_angle.py"), "--tiny", out],
                           env=env, capture_output=True, text=True)
        check(r.returncode == 0, "accel_outer_angle.py --tiny runs: " + r.stderr[-400:])
        with open(os.path.join(out, "accel_outer_angle.csv")) as f:
            rows = list(csv.DictReader(f))
        check(len(rows) == 1, f"one row, got {len(rows)}")
        row = rows[0]
        check(row["error_deg"] != "" and abs(float(row["error_deg"])) <= 3,
              f"placed within 3 deg of 25 deg from the load: {row}")
        check(row["covers"] == "True", f"the interval holds the angle: {row}")
        with open(os.path.join(out, "accel_outer_angle.md")) as f:
            md = f.read()
        check("| low | 1/1," in md and "20 kHz" in md, "the table names the case and the rate")
    finish()


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The sizing map of the detectability report (studies/sizing_map.py --tiny, issue 26): one
0.35 s run (a 3 deg outer pit under the radial load) acquired by the accelerometer at 20 and
50 kHz and sized by diagnose --size-method double-impulse. Checks the files and that every row
is either a size with an interval that holds it or a reason why not (the double impulse is
merged in this simulator's vibration at these rates: doc/ohmdem-post.md).
Usage: sizing_map_tests.py --exe OHMDEM --post OHMDEM_POST --src SOURCE_DIR"""
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
        r = subprocess.run(["/usr/bin/python3", os.path.join(a.src, "studies", "sizing_map.py"),
                            "--tiny", out], env=env, capture_output=True, text=True)
        check(r.returncode == 0, "sizing_map.py --tiny runs: " + r.stderr[-400:])
        with open(os.path.join(out, "sizing_map.csv")) as f:
            rows = list(csv.DictReader(f))
        check(len(rows) == 2, f"two rows (20 and 50 kHz), got {len(rows)}")
        for row in rows:
            check(row["channel"] == "acc" and row["defect"] == "outer", f"the case: {row}")
            if row["size_est_deg"]:
                lo, est = float(row["low"]), float(row["size_est_deg"])
                check(lo <= est and (not row["high"] or est <= float(row["high"])),
                      f"the interval holds the estimate: {row}")
            else:
                check("not determined" in row["note"], f"a reason when not sized: {row}")
        with open(os.path.join(out, "sizing_map.md")) as f:
            md = f.read()
        check("| acc | low |" in md and "20 kHz" in md and "50 kHz" in md,
              "the map's table names the channel, the noise and the rates")
        check(os.path.getsize(os.path.join(out, "sizing_map_acc.png")) > 1000, "the heatmap")
    finish()


if __name__ == "__main__":
    sys.exit(main())

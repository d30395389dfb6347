#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The sizing map of the detectability report (studies/sizing_map.py --tiny): one
0.35 s run (a 3 deg outer pit under the radial load) acquired by the accelerometer at 20 and
50 kHz and sized by diagnose --size-method double-impulse, and by the electrical chain and sized
by its pulse's shape on the committed radial outer banks (--size-method template). Checks the
files, that every accelerometer row is either a size with an interval that holds it or a reason
why not (the double impulse is merged in this simulator's vibration at these rates:
doc/ohmdem-post.md), and that the template sizes the pit within 15 % and covers it (the same
records in doc/report/sizing/template/template_tables.md: -3.9 % and +0.6 %).
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
        check(len(rows) == 4, f"four rows (20 and 50 kHz, two channels), got {len(rows)}")
        for row in rows:
            check(row["channel"] in ("acc", "template") and row["defect"] == "outer",
                  f"the case: {row}")
            if row["channel"] == "template":
                check(row["size_est_deg"] and abs(float(row["error_pct"])) < 15 and
                      row["covers"] == "True", f"the template: within 15 % and covered: {row}")
            elif row["size_est_deg"]:
                lo, est = float(row["low"]), float(row["size_est_deg"])
                check(lo <= est and (not row["high"] or est <= float(row["high"])),
                      f"the interval holds the estimate: {row}")
            else:
                check("not determined" in row["note"], f"a reason when not sized: {row}")
        with open(os.path.join(out, "sizing_map.md")) as f:
            md = f.read()
        check("| acc | low |" in md and "| template | low |" in md and "20 kHz" in md and
              "50 kHz" in md, "the map's table names the channels, the noise and the rates")
        for c in ("acc", "template"):
            check(os.path.getsize(os.path.join(out, f"sizing_map_{c}.png")) > 1000,
                  f"the {c} heatmap")
    finish()


if __name__ == "__main__":
    sys.exit(main())

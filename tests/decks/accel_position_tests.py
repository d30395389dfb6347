#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""An inner pit's place from the accelerometer and from the electrical channel
(studies/accel_position.py --tiny [--channel electrical]): one 0.35 s run (a 1 deg inner
pit at 135 deg on the ring, radial load) acquired by the accelerometer, then by the R chain, at
20 kHz with the deck's shaft angle, sized on the committed curves and placed by diagnose
(--size-method accel-curve; the pulse area). Checks the files, the place within the issue's
10 deg, and that the interval holds it.
Usage: accel_position_tests.py --exe OHMDEM --post OHMDEM_POST --src SOURCE_DIR"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

from deck_checks import check, finish


def tiny(a, out, channel):
    """studies/accel_position.py --tiny for one channel into out: its one row (the place checked)
    and its table."""
    env = dict(os.environ, OHMDEM=a.exe, POST=a.post)
    r = subprocess.run(["/usr/bin/python3", os.path.join(a.src, "studies", "accel_position.py"),
                        "--tiny", "--channel", channel, out],
                       env=env, capture_output=True, text=True)
    check(r.returncode == 0, f"accel_position.py --tiny --channel {channel} runs: " +
          r.stderr[-400:])
    stem = "accel_position" if channel == "acc" else "electrical_position"
    with open(os.path.join(out, stem + ".csv")) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == 1, f"{channel}: one row, got {len(rows)}")
    row = rows[0]
    check(row["error_deg"] != "" and abs(float(row["error_deg"])) <= 10,
          f"{channel}: placed within 10 deg of 135: {row}")
    check(row["covers"] == "True", f"{channel}: the interval holds the place: {row}")
    with open(os.path.join(out, stem + ".md")) as f:
        return row, f.read()


def main():
    p = argparse.ArgumentParser()
    for name in ("--exe", "--post", "--src"):  # ohmdem, ohmdem-post, the source tree
        p.add_argument(name, required=True)
    a = p.parse_args()
    with tempfile.TemporaryDirectory() as out:
        row, md = tiny(a, out, "acc")
        check(row["size_est_deg"] != "" and abs(float(row["size_est_deg"]) - 1) < 0.15,
              f"sized within 15 % on the committed curve: {row}")
        check("| low | 1/1," in md and "20 kHz" in md, "the table names the case and the rate")
        # the electrical channel on the same run (the committed 20 kHz chain curve): the pulse
        # area's load-zone peak
        row, md = tiny(a, out, "electrical")
        check("--channel electrical" in md, "the electrical table says how it was made")
    finish()


if __name__ == "__main__":
    sys.exit(main())

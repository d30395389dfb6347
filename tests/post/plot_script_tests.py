#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""What `ohmdem-post plot` asks gnuplot to draw (its script, kept by a wrapper given as
OHMDEM_GNUPLOT): the title names the run folder (and its defect) when the signal is a run's,
and the labels of close defect lines (3xBPFO 20 Hz beside 2xBPFI) stand at different heights.

Usage: plot_script_tests.py --post OHMDEM_POST
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--post", required=True)
    a = ap.parse_args()
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        print("SKIPPED: gnuplot not installed (Debian package gnuplot-nox)")
        return 77
    failed = False
    with tempfile.TemporaryDirectory(prefix="plot_script_") as work:
        run = os.path.join(work, "inner_defect")
        os.makedirs(run)
        # 0.1 s at 20 kHz of pulses at BPFI of the 6208 at 500 rad/s (624.8 Hz)
        with open(os.path.join(run, "signal.txt"), "w") as f:
            f.write("# time R\n")
            for i in range(2000):
                t = i / 20000
                f.write(f"{t!r} {1.38 + 0.1 * (math.sin(2 * math.pi * 624.8 * t) > 0.95)!r}\n")
        with open(os.path.join(run, "run.json"), "w") as f:
            json.dump({"bearing": "machado2014", "omega_inner": 500, "nb": 13, "db": 0.0126,
                       "dp": 0.0606, "defect": "inner", "t_sliding_end": 0.0,
                       "status": "finished"}, f)
        wrapper = os.path.join(work, "gnuplot")
        with open(wrapper, "w") as f:
            f.write(f"#!/bin/sh\ncp \"$1\" {work}/kept.gp\nexec {gnuplot} \"$@\"\n")
        os.chmod(wrapper, 0o755)
        env = dict(os.environ, OHMDEM_GNUPLOT=wrapper)
        r = subprocess.run([a.post, "plot", "--kind", "spectrum", "--output",
                            os.path.join(work, "s.png"), os.path.join(run, "signal.txt")],
                           env=env, capture_output=True, text=True)
        script = open(os.path.join(work, "kept.gp")).read() if r.returncode == 0 else ""
        title = re.search(r"^set title '(.*)'$", script, re.M)
        ok = title is not None and title.group(1).startswith("run inner_defect (inner defect): ")
        print(("ok   " if ok else "FAIL ") + f"the title names the run: "
              f"{title.group(1) if title else r.stderr.strip()}")
        failed |= not ok
        heights = {m.group(1): float(m.group(2)) for m in re.finditer(
            r"^set label \d+ '([^']+)' at [^,]+, graph ([0-9.]+)", script, re.M)}
        ok = ("3xBPFO" in heights and "2xBPFI" in heights
              and heights["3xBPFO"] != heights["2xBPFI"])
        print(("ok   " if ok else "FAIL ") + f"3xBPFO and 2xBPFI labels at different heights: "
              f"{heights.get('3xBPFO')} {heights.get('2xBPFI')}")
        failed |= not ok
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

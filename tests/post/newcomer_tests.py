#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""A newcomer's first hour with ohmdem-post (issue: nothing runs that was not asked for ...).

  plot_script     what `plot` asks gnuplot to draw (its script, kept by a wrapper given as
                  OHMDEM_GNUPLOT): the title names the run folder (and its defect) when the
                  signal is a run's, and the labels of close defect lines (3xBPFO 20 Hz beside
                  2xBPFI) stand at different heights
  diagnose_floor  `diagnose` of a simulated healthy R at the numerical floor (3e-7 of its mean,
                  one 2e-5 ohm blip: kurtosis in the thousands) says so and reads healthy; a
                  signal with a defect's spread (1e-2) gets no such line

Usage: newcomer_tests.py TEST --post OHMDEM_POST
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


def run_folder(work, name, values, defect="none"):
    """A run folder as the deck writes it: signal.txt (20 kHz) and run.json (the 6208)."""
    run = os.path.join(work, name)
    os.makedirs(run)
    with open(os.path.join(run, "signal.txt"), "w") as f:
        f.write("# time R\n")
        for i, v in enumerate(values):
            f.write(f"{i / 20000!r} {v!r}\n")
    with open(os.path.join(run, "run.json"), "w") as f:
        json.dump({"bearing": "machado2014", "omega_inner": 500, "nb": 13, "db": 0.0126,
                   "dp": 0.0606, "defect": defect, "t_sliding_end": 0.0,
                   "status": "finished"}, f)
    return os.path.join(run, "signal.txt")


def diagnose_floor(a, work):
    import random
    rng = random.Random(1)
    # as the healthy demo run: R = 1.3838 ohm varying smoothly by 4e-7 ohm (no white noise: a
    # simulation), one blip of 2e-5 ohm
    healthy = [1.3838 + 4e-7 * math.sin(2 * math.pi * 31.5 * i / 20000)
               + 1e-7 * math.sin(2 * math.pi * 79.6 * i / 20000) for i in range(4000)]
    healthy[2000] += 2e-5
    failed = False
    r = subprocess.run([a.post, "diagnose", run_folder(work, "healthy", healthy)],
                       capture_output=True, text=True)
    ok = (r.returncode == 0 and re.search(r"^floor: +R varies by [0-9.e-]+ of its mean", r.stdout,
                                          re.M) is not None
          and re.search(r"^verdict: +healthy", r.stdout, re.M) is not None)
    print(("ok   " if ok else "FAIL ") + "healthy run at the numerical floor: said, verdict "
          f"healthy (exit {r.returncode}): "
          f"{[l for l in r.stdout.splitlines() if l.startswith(('floor', 'verdict'))]}")
    failed |= not ok
    r = subprocess.run([a.post, "diagnose", "--format", "json",
                        os.path.join(work, "healthy", "signal.txt")], capture_output=True, text=True)
    floor = json.loads(r.stdout).get("numerical_floor") if r.returncode == 0 else None
    ok = isinstance(floor, str) and "numerical floor" in floor
    print(("ok   " if ok else "FAIL ") + f"the JSON carries it: numerical_floor = {floor!r}")
    failed |= not ok
    noisy = [1.3838 * (1 + 1e-2 * rng.gauss(0, 1)) for _ in range(4000)]
    r = subprocess.run([a.post, "diagnose", run_folder(work, "noisy", noisy)],
                       capture_output=True, text=True)
    ok = r.returncode == 0 and "floor:" not in r.stdout
    print(("ok   " if ok else "FAIL ") + "a spread of 1e-2: no floor line")
    failed |= not ok
    return 1 if failed else 0


def plot_script(a, work):
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        print("SKIPPED: gnuplot not installed (Debian package gnuplot-nox)")
        return 77
    failed = False
    if True:
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


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("test")
    ap.add_argument("--post", required=True)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="newcomer_") as work:
        return {"plot_script": plot_script, "diagnose_floor": diagnose_floor}[a.test](a, work)


if __name__ == "__main__":
    sys.exit(main())

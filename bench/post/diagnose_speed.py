#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""How long `ohmdem-post diagnose` takes on a 10 s record sampled at 48 kHz, on one core.

  /usr/bin/python3 bench/post/diagnose_speed.py [--post build/ohmdem-post] [--repeats R]
                                                [--seconds S] [--rate HZ]

The record: a CWRU-like MAT v5 file (variables DE_time, RPM) of an inner-race fault of the
6205-2RS JEM at 1797 rpm: decaying 3 kHz resonance bursts at BPFI (5.4152 fr), modulated once
per revolution, in white noise (seed 1). Timed, best of R runs after one warm-up, pinned to
core 0 (taskset) when available: `stats` on the same file (reading it), `diagnose --no-size`
(detection and identification) and `diagnose` with its defaults. Prints each time, its ratio
to the 1 s goal, and the verdict (it must read inner).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np
import scipy.io

HERE = os.path.dirname(os.path.abspath(__file__))
GOAL_S = 1.0


def record(path, seconds, rate):
    rng = np.random.default_rng(1)
    fr = 1797 / 60
    bpfi = 5.4152 * fr
    n = int(seconds * rate)
    t = np.arange(n) / rate
    x = 0.05 * rng.standard_normal(n)
    burst_t = np.arange(int(0.004 * rate)) / rate
    burst = np.exp(-burst_t / 0.0008) * np.sin(2 * np.pi * 3000 * burst_t)
    for k in range(int(seconds * bpfi)):
        t0 = k / bpfi
        i = int(t0 * rate)
        a = 0.3 * (1 + 0.5 * np.cos(2 * np.pi * fr * t0))
        seg = burst[: max(0, min(len(burst), n - i))]
        x[i:i + len(seg)] += a * seg
    scipy.io.savemat(path, {"DE_time": x.reshape(-1, 1), "RPM": np.array([[1797.0]])})
    return t


def timed(cmd, repeats):
    subprocess.run(cmd, capture_output=True, check=True)  # warm-up (file cache)
    best = float("inf")
    out = None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = subprocess.run(cmd, capture_output=True, text=True, check=True)
        best = min(best, time.perf_counter() - t0)
    return best, out.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--post", default=os.path.join(HERE, "..", "..", "build", "ohmdem-post"))
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--seconds", type=float, default=10)
    ap.add_argument("--rate", type=float, default=48000)
    a = ap.parse_args()
    pin = ["taskset", "-c", "0"] if shutil.which("taskset") else []
    with tempfile.TemporaryDirectory(prefix="diagnose_speed_") as wd:
        mat = os.path.join(wd, "inner_48k.mat")
        record(mat, a.seconds, a.rate)
        common = [mat, "--variable", "DE_time", "--rate", f"{a.rate:g}"]
        diag = common + ["--rpm-variable", "RPM", "--bearing", "6205-2RS_JEM"]
        print(f"record: {a.seconds:g} s at {a.rate:g} Hz ({int(a.seconds * a.rate)} samples), "
              f"MAT v5; best of {a.repeats} runs{' on core 0' if pin else ''}")
        print(f"{'command':<34} {'time_s':>8} {'/ goal':>8}")
        rows = [("stats (reading the record)", [a.post, "stats", *common]),
                ("diagnose --no-size", [a.post, "diagnose", *diag, "--no-size", "--format",
                                        "json"]),
                ("diagnose", [a.post, "diagnose", *diag, "--format", "json"])]
        verdict = None
        for name, cmd in rows:
            t, out = timed(pin + cmd, a.repeats)
            print(f"{name:<34} {t:8.3f} {t / GOAL_S:8.2f}")
            if name.startswith("diagnose"):
                verdict = json.loads(out)["defect"]
        print(f"verdict: {verdict} (an inner-race fault)")
        return 0 if verdict == "inner" else 1


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The table of doc/methods/lubricated_contact.md "Defects: a pit under the film": the Cb dip of each
crossing of a pit by a ball (inner, outer, ball defect; 1 deg, 5 um, 6208 deck at the paper's
point, dt = 1e-5 s, every step from 16 to 85 ms), relative to the healthy bearing's median Cb.
Per crossing (the steps with n_masked > 0, widened by 0.5 ms on either side):
  dip    1 - min Cb / Cb0;
  width  how long Cb stays below Cb0 (1 - dip/2) (the dip's full width at half depth);
  lead   how long before the first masked step Cb first falls below Cb0 (1 - 1e-5) (ten
         times the healthy spread): the pit entering the wetted circle;
the overshoot after it (max Cb / Cb0 - 1: the ball strikes the far edge) and the largest |Z|
of the crossing relative to the healthy median. (The dry R is the
mechanics': the pit's strip does not change it.)
and, with --post, ohmdem-post diagnose's verdict on the Cb column from 16 ms.
Usage: lubricated_defect_table.py --exe OHMDEM [--exe OTHER ...] [--post OHMDEM_POST]
(one table per executable)
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "decks"))
from bearing_tests import Runner, read_signal  # noqa: E402

DT, T_STEADY, TEND = 1e-5, 0.016, 0.085
WIDEN = 0.5e-3  # s: the pit passes a 1.26 mm wetted circle in ~0.4 ms at 7 m/s


def crossings(sig):
    s = sig["time"] >= T_STEADY
    idx = np.nonzero(s & (sig["n_masked"] > 0))[0]
    return np.split(idx, np.nonzero(np.diff(idx) > 1)[0] + 1) if len(idx) else []


def table(exe, src, wd, post=None):
    r = Runner(os.path.abspath(exe), src, wd)
    healthy, _ = r.run("healthy", lubricant="VG68", tend=0.02, dt=DT, nout=1)
    h = read_signal(healthy)
    s = h["time"] >= T_STEADY
    cb0, z0 = (np.median(h[k][s]) for k in ("Cb", "Zabs"))
    print(f"{exe}: healthy Cb {cb0 * 1e12:.3f} pF, |Z| {z0 / 1e3:.3f} kOhm")
    print("| defect | Cb dip: mean (range) | width at half depth | lead before the zone "
          "| overshoot: mean (max) | |Z| rise |")
    rows = {}
    for kind in ("inner", "outer", "ball"):
        out, _ = r.run(kind, lubricant="VG68", defect=kind, size=1.0, tend=TEND, dt=DT, nout=1)
        sig = read_signal(out)
        t, cb = sig["time"], sig["Cb"]
        dips, widths, leads, zs, overs = [], [], [], [], []
        for p in crossings(sig)[1:-1]:  # whole windows only
            w = np.nonzero((t >= t[p[0]] - WIDEN) & (t <= t[p[-1]] + WIDEN))[0]
            dip = 1 - cb[w].min() / cb0
            dips.append(dip)
            widths.append(DT * np.count_nonzero(cb[w] < cb0 * (1 - dip / 2)))
            below = w[cb[w] < cb0 * (1 - 1e-5)]
            leads.append(t[p[0]] - t[below[0]] if len(below) else 0.0)
            zs.append(sig["Zabs"][w].max() / z0 - 1)
            overs.append(cb[w].max() / cb0 - 1)
        d = 100 * np.array(dips)
        rows[kind] = (d, widths, leads)
        print(f"| {kind} ({len(d)} crossings) | {d.mean():.2f} % ({d.min():.2f}-{d.max():.2f} %) "
              f"| {1e3 * np.mean(widths):.3f} ms | {1e3 * np.mean(leads):.3f} ms "
              f"| {100 * np.mean(overs):.2f} % ({100 * np.max(overs):.2f} %) "
              f"| {100 * np.mean(zs):.2f} % |")
        if post:
            rep = subprocess.run([post, "diagnose", "--column", "Cb", "--from", str(T_STEADY),
                                  os.path.join(out, "signal.txt")], capture_output=True, text=True)
            lines = [l.strip() for l in rep.stdout.splitlines() if l.strip() and l[0] != "#"]
            print("    " + " / ".join(lines[:4]))
    return rows


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", action="append", required=True)
    p.add_argument("--post")
    a = p.parse_args()
    src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    for exe in a.exe:
        with tempfile.TemporaryDirectory(prefix="ohmdem_lubdef_table_") as wd:
            table(exe, src, wd, a.post)


if __name__ == "__main__":
    main()

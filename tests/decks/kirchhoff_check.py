#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Independent check of compute network/resistance's local array (a `dump local` of its 7
columns: atom, partner, conductance, current, drop, masked, electrode), with numpy only.

Per step: Kirchhoff's current law at every particle (the currents entering it through its
contacts sum to zero: rows where it is the atom count +current, rows where it is the partner
-current), the current out of the high electrode and into the low one equal to I, and Ohm's
law on every row (conductance * drop = current). Masked rows carry nothing.
Usage: kirchhoff_check.py DUMP --current I [--voltage-col SIGNAL]"""
import argparse
import sys

import numpy as np


def read_local_dump(path):
    """{step: array (rows, 7)} from a LAMMPS/LIGGGHTS `dump local` file."""
    steps, lines = {}, open(path).read().split("\n")
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            n = int(lines[k + 3])
            k += 4
            while not lines[k].startswith("ITEM: ENTRIES"):
                k += 1
            rows = [list(map(float, lines[k + 1 + r].split())) for r in range(n)]
            steps[step] = np.array(rows, dtype=float).reshape(n, 7)
            k += 1 + n
        else:
            k += 1
    return steps


def check_step(rows, current, tol=1e-9):
    """Returns (max node imbalance / I, high sum, low sum, max Ohm error / I, conducting rows)."""
    atom, partner = rows[:, 0].astype(np.int64), rows[:, 1].astype(np.int64)
    g, i, v, masked, el = rows[:, 2], rows[:, 3], rows[:, 4], rows[:, 5], rows[:, 6]
    bad = []
    if np.any(~np.isfinite(rows)):
        bad.append("a non-finite value")
    if np.any((masked == 1) & ((g != 0) | (i != 0))):
        bad.append("a masked contact with a conductance or a current")
    if np.any((partner != 0) & (el != 0)):
        bad.append("a particle partner marked as an electrode")
    ohm = np.max(np.abs(g * v - i), initial=0.0) / current
    if ohm > tol:
        bad.append(f"conductance * drop != current by {ohm:.3g} I")
    nodes = np.union1d(atom, partner[partner != 0])
    inflow = np.zeros(len(nodes))
    np.add.at(inflow, np.searchsorted(nodes, atom), i)
    pp = partner != 0
    np.add.at(inflow, np.searchsorted(nodes, partner[pp]), -i[pp])
    kcl = np.max(np.abs(inflow), initial=0.0) / current
    high, low = i[el == 1].sum(), -i[el == -1].sum()
    return kcl, high, low, ohm, int(np.count_nonzero(i)), bad


def check_dump(path, current, tol=1e-9, need_current=True):
    steps = read_local_dump(path)
    if not steps:
        sys.exit(f"FAIL: {path}: no step")
    worst = 0.0
    for step, rows in sorted(steps.items()):
        kcl, high, low, ohm, carrying, bad = check_step(rows, current, tol)
        if carrying == 0:
            continue  # before the first contact (a bearing at step 0)
        if abs(high - current) > tol * current or abs(low - current) > tol * current:
            bad.append(f"electrode currents {high!r} (high) {low!r} (low), I = {current!r}")
        if kcl > tol:
            bad.append(f"a particle's currents sum to {kcl:.3g} I")
        if bad:
            sys.exit(f"FAIL: {path} step {step}: " + "; ".join(bad))
        worst = max(worst, kcl, abs(high - current) / current, abs(low - current) / current, ohm)
    carrying_steps = sum(1 for r in steps.values() if np.count_nonzero(r[:, 3]))
    if need_current and carrying_steps == 0:
        sys.exit(f"FAIL: {path}: no step carries current")
    return steps, worst


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dump")
    ap.add_argument("--current", type=float, required=True)
    ap.add_argument("--tol", type=float, default=1e-9)
    a = ap.parse_args()
    steps, worst = check_dump(a.dump, a.current, a.tol)
    print(f"ok: {len(steps)} steps, worst relative Kirchhoff/Ohm error {worst:.3g}")


if __name__ == "__main__":
    main()

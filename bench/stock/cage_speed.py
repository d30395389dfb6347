#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Cage speed after the sliding phase, from a bearing time series.

usage: cage_speed.py FILE [--theory W] [--tol 0.01] [--window 10]

FILE: text with a '#'-prefixed (or bare) header line naming the columns, one row per output
step; the columns used are the first whose names start with 'time' and 'omega_cage'
(bench/stock cage.txt, inputs/bearing_6208 signal.txt). Prints one line:
  t_slide_s <t> omega_cage_rad_s <w> error_pct <e> samples <n>
t_slide: end of the sliding phase = first time from which the running mean of omega_cage
over --window samples stays within --tol (relative) of the final value (mean of the last
20 % of the samples). omega_cage: mean over the samples after t_slide. error: against
--theory (default 2 pi FTF of the SKF 6208 at 500 rad/s: 250 (1 - d/D) rad/s, d and D from
its catalog file, studies/common.py).
Exit 1 (with t_slide 'none') when the run never settles.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "studies"))
import common  # noqa: E402  (the catalog's machado2014, the paper's bearing)


def read_columns(path):
    header, rows = None, []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            words = s.lstrip('#').split()
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                header = words
    if header is None or not rows:
        sys.exit('ERROR: %s: no header line or no data rows' % path)
    def col(prefix):
        for i, h in enumerate(header):
            if h.startswith(prefix):
                return i
        sys.exit('ERROR: %s: no column starting with %r in header %s' % (path, prefix, header))
    data = np.array([r for r in rows if len(r) == len(header)])
    # The ball set's orbital speed is what FTF describes: ohmdem's signal.txt has it as
    # omega_balls (its omega_cage is the cage body, which floats within its pocket play).
    names = [n.lower() for n in header]
    speed = 'omega_balls' if any(n.startswith('omega_balls') for n in names) else 'omega_cage'
    return data[:, col('time')], data[:, col(speed)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('file')
    ap.add_argument('--theory', type=float, default=common.Bearing('machado2014').cage_speed(500.0))
    ap.add_argument('--tol', type=float, default=0.01)
    ap.add_argument('--window', type=int, default=10)
    a = ap.parse_args()
    t, w = read_columns(a.file)
    n = len(t)
    if n < 2 * a.window:
        print('t_slide_s none omega_cage_rad_s nan error_pct nan samples %d' % n)
        return 1
    final = w[-max(1, n // 5):].mean()
    k = max(1, a.window)
    run = np.convolve(w, np.ones(k) / k, mode='valid')        # run[i] = mean of w[i:i+k]
    bad = np.nonzero(np.abs(run - final) > a.tol * abs(final))[0]
    start = 0 if len(bad) == 0 else bad[-1] + 1
    # the steady part must be at least as long as the averaging window used to find it
    if final == 0 or start + k > n - k:
        print('t_slide_s none omega_cage_rad_s %.6g error_pct nan samples %d' % (final, n))
        return 1
    i0 = start + k - 1                                       # last sample of the first good window
    wm = w[i0:].mean()
    print('t_slide_s %.6g omega_cage_rad_s %.6g error_pct %+.4f samples %d'
          % (t[i0], wm, 100.0 * (wm - a.theory) / a.theory, n - i0))
    return 0


if __name__ == '__main__':
    sys.exit(main())

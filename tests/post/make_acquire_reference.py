#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Reference values for the acquire tests (tests/post/dsp/test_butterworth.cpp and
test_acquire.cpp), computed with scipy (Debian python3-scipy): the anti-alias Butterworth
filter's sections and its output.

Writes into reference/ (next to this script):
  butter_sos.txt       scipy.signal.butter(N, fc, fs=fs, output='sos') over a grid of orders and
                       cut-offs, one row per section: "N fc fs section b0 b1 b2 a0 a1 a2"
  acquire_input.txt    a busy test signal (one value per line, %.17g: read back bit-identical)
  acquire_sosfilt.txt  its filtered versions, one column per case of CASES, in that order:
                       sosfilt(sos, x) (zero initial state) and
                       sosfilt(sos, x, zi=sosfilt_zi(sos) * x[0]) (steady initial state)

Run:  /usr/bin/python3 tests/post/make_acquire_reference.py   (deterministic: fixed seed)
"""
import os

import numpy as np
import scipy.signal

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference")

ORDERS = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 15, 16, 20]
# cut-off as a fraction of the sampling rate, from far below to just under Nyquist
FRACTIONS = [0.0005, 0.004, 0.02, 0.1, 0.2, 0.25, 0.3, 0.4, 0.45, 0.49]
RATES = [1e6, 12000.0]
# (order, cut-off Hz) at fs = 1 MHz, each filtered from a zero and from a steady state
CASES = [(4, 20000.0), (5, 100000.0), (8, 150000.0), (1, 3000.0)]
FS = 1e6


def main():
    os.makedirs(HERE, exist_ok=True)
    with open(os.path.join(HERE, "butter_sos.txt"), "w") as f:
        f.write("# scipy %s: scipy.signal.butter(N, fc, fs=fs, output='sos')\n" % scipy.__version__)
        f.write("# N fc fs section b0 b1 b2 a0 a1 a2\n")
        for fs in RATES:
            for n in ORDERS:
                for r in FRACTIONS:
                    fc = r * fs
                    sos = scipy.signal.butter(n, fc, fs=fs, output="sos")
                    for i, row in enumerate(sos):
                        f.write("%d %.17g %.17g %d %s\n" % (n, fc, fs, i,
                                                            " ".join("%.17g" % v for v in row)))
    rng = np.random.default_rng(20261123)
    n = 1500
    t = np.arange(n) / FS
    # a level (as R's 1.39 ohm), a tone in the pass band, one above, white noise and a step
    x = (1.39 + 0.2 * np.sin(2 * np.pi * 7000 * t + 0.4) + 0.1 * np.sin(2 * np.pi * 210000 * t)
         + rng.normal(0, 0.05, n) + 0.3 * (np.arange(n) >= 750))
    with open(os.path.join(HERE, "acquire_input.txt"), "w") as f:
        for v in x:
            f.write("%.17g\n" % v)
    x = np.loadtxt(os.path.join(HERE, "acquire_input.txt"))
    cols = []
    for order, fc in CASES:
        sos = scipy.signal.butter(order, fc, fs=FS, output="sos")
        cols.append(scipy.signal.sosfilt(sos, x))
        cols.append(scipy.signal.sosfilt(sos, x, zi=scipy.signal.sosfilt_zi(sos) * x[0])[0])
    header = "scipy %s sosfilt at fs = %g Hz; columns: %s, each zero then steady" % (
        scipy.__version__, FS, " ".join("N=%d,fc=%g" % c for c in CASES))
    np.savetxt(os.path.join(HERE, "acquire_sosfilt.txt"), np.column_stack(cols), fmt="%.17g",
               header=header)


if __name__ == "__main__":
    main()

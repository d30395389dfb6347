#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Reference for the order-tracking tests (tests/post/dsp/test_order_tracking.cpp), with numpy/scipy.

The record (synthesised identically by the test): fs = 2000 Hz, 4000 samples (2 s), shaft
frequency rising linearly fr(t) = 10 + 10 t Hz, so the shaft angle is known in closed form,
theta(t) = 2 pi (10 t + 5 t^2) (40 revolutions), and the signal is
  x(t) = cos(5.3 theta) + 0.4 cos(11.2 theta + 0.5) + 0.3 cos(2 pi 900 t).
The 900 Hz tone is fixed in time: at 32 samples per revolution (angle Nyquist order 16, i.e.
160..480 Hz over the run-up) it must be removed by the anti-alias filter, while orders 5.3 and
11.2 pass.

Writes reference/orders_chirp.txt: rows "order amplitude" of the one-sided amplitude spectrum
(scipy.signal.periodogram, Hann window, 'spectrum' scaling, mean removed; amplitude =
sqrt(2 P) off DC and Nyquist) of the exact angle-domain signal
  y_k = cos(5.3 phi_k) + 0.4 cos(11.2 phi_k + 0.5),  phi_k = 2 pi k / 32,
for revolutions 2 to 38 (k = 64 .. 1215), i.e. the same resampled data the test takes from
ohmdem-post's resampler.

Run:  /usr/bin/python3 tests/post/make_order_reference.py
"""
import os

import numpy as np
import scipy.signal

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference")
S = 32  # samples per revolution


def main():
    k = np.arange(2 * S, 38 * S)
    phi = 2 * np.pi * k / S
    y = np.cos(5.3 * phi) + 0.4 * np.cos(11.2 * phi + 0.5)
    f, p = scipy.signal.periodogram(y, fs=S, window="hann", detrend="constant",
                                    scaling="spectrum")
    amp = np.sqrt(2 * p)
    amp[0] = np.sqrt(p[0])
    if y.size % 2 == 0:
        amp[-1] = np.sqrt(p[-1])
    np.savetxt(os.path.join(HERE, "orders_chirp.txt"), np.column_stack([f, amp]), fmt="%.17g")


if __name__ == "__main__":
    main()

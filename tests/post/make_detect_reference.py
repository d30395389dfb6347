#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Reference values for the detection tests (tests/post/dsp/test_detect.cpp), from scipy.stats.

Writes reference/detect_reference.txt (next to this script), one case per line, "%.17g":
  kurtosis N B2 Z P     scipy.stats.kurtosistest (Anscombe-Glynn, alternative='greater') on
                        seeded samples of N values (Gaussian, Student t, uniform, impulses):
                        B2 = scipy.stats.kurtosis(x, fisher=False), Z its statistic, P = p-value
  normal_isf P Z        scipy.stats.norm.isf(P)
  t_sf NU T P           scipy.stats.t.sf(T, NU) (scipy's t.isf itself is good to ~1e-8 only:
                        its sf at its isf misses P by that much)
  crest N P U           the level U with P(max_i |x_i| > U) = P for N independent N(0, 1):
                        scipy.stats.norm.isf((1 - (1 - P) ** (1 / N)) / 2)

Run:  /usr/bin/python3 tests/post/make_detect_reference.py   (deterministic: fixed seeds)
"""
import os

import numpy as np
import scipy.stats as st

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference")


def main():
    rng = np.random.default_rng(20261123)
    lines = []
    for n in (20, 21, 50, 257, 1000, 4096, 100000):
        samples = {"gauss": rng.normal(0, 1, n), "t5": rng.standard_t(5, n),
                   "uniform": rng.uniform(-1, 1, n),
                   "impulses": rng.normal(0, 1, n) + 8.0 * (np.arange(n) % 19 == 3)}
        for x in samples.values():
            b2 = st.kurtosis(x, fisher=False)
            z, p = st.kurtosistest(x, alternative="greater")
            lines.append(f"kurtosis {n} {b2:.17g} {z:.17g} {p:.17g}")
    for p in (0.5, 0.1, 1e-3, 1e-6, 1e-9, 1e-12):
        lines.append(f"normal_isf {p:.17g} {st.norm.isf(p):.17g}")
    for nu in (1, 2, 5, 9, 15, 30, 100):
        for t in (0.5, 1.5, 3.0, 4.5, 8.0, 40.0):
            lines.append(f"t_sf {nu} {t:.17g} {st.t.sf(t, nu):.17g}")
    for n in (100, 4096, 122136, 243938):
        for p in (0.05, 1e-3, 1e-6):
            u = st.norm.isf(-np.expm1(np.log1p(-p) / n) / 2)
            lines.append(f"crest {n} {p:.17g} {u:.17g}")
    with open(os.path.join(HERE, "detect_reference.txt"), "w") as f:
        f.write("# written by tests/post/make_detect_reference.py (scipy "
                f"{__import__('scipy').__version__}); do not edit\n")
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()

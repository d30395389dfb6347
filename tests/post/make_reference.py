#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Reference values for the ohmdem-post tests, computed with numpy/scipy (Debian python3-scipy).

Writes into reference/ (next to this script):
  sig_<name>.txt          the input vectors, one value per line, printed to round-trip (%.17g)
  indicators.json         per vector: peak, mean, rms, std, skewness, kurtosis (Pearson), crest,
                          shape, impulse, clearance, as defined in doc/post/stats.md
  hilbert_<name>.txt      |scipy.signal.hilbert(x)| for two vectors (odd and even length)
  welch_<name>.txt        scipy.signal.welch PSD (hann, nperseg 256, 50 % overlap, detrend
                          'constant', density, one-sided) as "frequency psd" rows
  periodogram_gauss.txt   scipy.signal.periodogram (boxcar, no detrend, 'spectrum' scaling)

Run:  /usr/bin/python3 tests/post/make_reference.py   (deterministic: fixed seeds)
"""
import json
import os

import numpy as np
import scipy
import scipy.signal
import scipy.stats

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference")


def vectors():
    rng = np.random.default_rng(20240605)
    v = {}
    v["gauss"] = rng.normal(0.3, 1.7, 1000)
    # a resistance-like trace: 1.39 ohm level, +8.3 % rectangles 58 samples long every 1600
    # samples, small noise, 8000 samples (the shape of our defect signals)
    n = 8000
    r = np.full(n, 1.39)
    for start in range(300, n, 1600):
        r[start:start + 58] *= 1.083
    v["rect_train"] = r + rng.normal(0, 0.002, n)
    t = np.arange(2048) / 2048.0
    v["sine"] = 0.7 * np.sin(2 * np.pi * 37.25 * t + 0.3) + 0.05
    v["exponential"] = rng.exponential(2.5, 777)
    v["impulses"] = np.where(np.arange(4001) % 400 == 17, 5.0, 0.0) + rng.normal(0, 0.1, 4001)
    v["small_ints"] = np.array([1.0, 2.0, 3.0, 4.0, 100.0])
    v["negative"] = -np.abs(rng.normal(2.0, 0.5, 501))
    return v


def indicators(x):
    x = np.asarray(x, dtype=float)
    peak = np.max(np.abs(x))
    rms = np.sqrt(np.mean(x ** 2))
    mabs = np.mean(np.abs(x))
    return {
        "n": int(x.size),
        "peak": float(peak),
        "mean": float(np.mean(x)),
        "rms": float(rms),
        "std": float(np.std(x)),  # ddof = 0
        "skewness": float(scipy.stats.skew(x)),  # bias = True
        "kurtosis": float(scipy.stats.kurtosis(x, fisher=False)),  # Pearson
        "crest": float(peak / rms),
        "shape": float(rms / mabs),
        "impulse": float(peak / mabs),
        "clearance": float(peak / np.mean(np.sqrt(np.abs(x))) ** 2),
    }


def write_vector(path, x):
    with open(path, "w") as f:
        for value in x:
            f.write("%.17g\n" % value)


def main():
    os.makedirs(HERE, exist_ok=True)
    v = vectors()
    ref = {"generator": "tests/post/make_reference.py",
           "numpy": np.__version__, "scipy": scipy.__version__, "vectors": {}}
    for name, x in v.items():
        write_vector(os.path.join(HERE, "sig_%s.txt" % name), x)
        # the values as read back from the text file (bit-identical by %.17g)
        xr = np.loadtxt(os.path.join(HERE, "sig_%s.txt" % name), ndmin=1)
        assert np.array_equal(xr, x)
        ref["vectors"][name] = indicators(xr)
    with open(os.path.join(HERE, "indicators.json"), "w") as f:
        json.dump(ref, f, indent=2, sort_keys=True)
        f.write("\n")
    for name in ("gauss", "impulses"):  # even and odd lengths
        write_vector(os.path.join(HERE, "hilbert_%s.txt" % name),
                     np.abs(scipy.signal.hilbert(v[name])))
    for name in ("gauss", "rect_train"):
        f, p = scipy.signal.welch(v[name], fs=1000.0, window="hann", nperseg=256, noverlap=128,
                                  detrend="constant", scaling="density")
        np.savetxt(os.path.join(HERE, "welch_%s.txt" % name), np.column_stack([f, p]), fmt="%.17g")
    f, p = scipy.signal.periodogram(v["gauss"], fs=1000.0, window="boxcar", detrend=False,
                                    scaling="spectrum")
    np.savetxt(os.path.join(HERE, "periodogram_gauss.txt"), np.column_stack([f, p]), fmt="%.17g")


if __name__ == "__main__":
    main()

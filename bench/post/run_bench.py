#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The post-processing benchmark: spectrum and envelope of a 1e7-sample signal, samples per second,
ohmdem-post's library (FFTW) against numpy/scipy (numpy.fft, scipy.signal.hilbert) on the same
machine in the same run, on the same signal.

  /usr/bin/python3 bench/post/run_bench.py [path/to/bench_post] [--samples N] [--repeats R]

Operations, identical on both sides:
  spectrum  x - mean(x), times a periodic Hann window, real FFT, |X| 2/sum(w)
  envelope  |analytic signal| of the whole band (scipy.signal.hilbert), then the spectrum above
            of the envelope
Best of R repeats after one warm-up; ratio > 1 means ohmdem-post is faster.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import scipy
import scipy.signal

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "studies"))
from common import BASE  # noqa: E402  (the source tree: studies/common.py)


def spectrum(x, w, wsum):
    y = (x - x.mean()) * w
    return np.abs(np.fft.rfft(y)) * (2.0 / wsum)


def envelope_spectrum(x, w, wsum):
    env = np.abs(scipy.signal.hilbert(x))
    return spectrum(env, w, wsum)


def best_of(f, repeats):
    f()  # warm-up
    best = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - t0)
    return best


def main():
    default_exe = os.path.join(BASE, "build", "bench", "bench_post")
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("exe", nargs="?", default=default_exe)
    ap.add_argument("--samples", type=int, default=10_000_000)
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    if not os.access(args.exe, os.X_OK):
        sys.exit("ERROR: bench executable not found: %s (cmake --build build --target bench_post)"
                 % args.exe)
    n = args.samples
    t = np.arange(n) * 1e-6
    rng = np.random.default_rng(1)
    x = 1.39 + np.where(np.mod(t, 1 / 624.8) < 58e-6, 0.115, 0.0) + rng.normal(0, 0.003, n)
    w = scipy.signal.get_window("hann", n)  # periodic, as ohmdem-post
    wsum = w.sum()

    with tempfile.NamedTemporaryFile(suffix=".f64", delete=False) as f:
        x.astype("<f8").tofile(f)
        path = f.name
    try:
        out = subprocess.run([args.exe, str(n), str(args.repeats), path], check=True,
                             capture_output=True, text=True).stdout
    finally:
        os.unlink(path)
    ours = json.loads(out)

    ts = best_of(lambda: spectrum(x, w, wsum), args.repeats)
    te = best_of(lambda: envelope_spectrum(x, w, wsum), args.repeats)
    # same numbers on both sides (checks that the work is the same)
    s = spectrum(x, w, wsum)
    e = envelope_spectrum(x, w, wsum)
    ds = abs(s[len(s) // 3] - ours["check_spectrum"]) / max(abs(s).max(), 1e-300)
    de = abs(e[len(e) // 7] - ours["check_envelope"]) / max(abs(e).max(), 1e-300)

    print("post benchmark: %d samples, best of %d, numpy %s, scipy %s" %
          (n, args.repeats, np.__version__, scipy.__version__))
    print("%-10s %14s %14s %14s %14s %8s" % ("step", "ohmdem s", "numpy/scipy s", "ohmdem S/s",
                                               "numpy S/s", "ratio"))
    for name, mine, theirs in (("spectrum", ours["spectrum_s"], ts),
                               ("envelope", ours["envelope_s"], te)):
        print("%-10s %14.4f %14.4f %14.3e %14.3e %8.2f" %
              (name, mine, theirs, n / mine, n / theirs, theirs / mine))
    print("agreement of a spectrum bin: %.1e, of an envelope-spectrum bin: %.1e (relative to max)"
          % (ds, de))


if __name__ == "__main__":
    main()

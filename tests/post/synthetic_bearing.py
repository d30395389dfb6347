#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""An independent model of a faulty rolling bearing's vibration (numpy/scipy, no ohmdem code).

The textbook impulse model (Randall & Antoni, "Rolling element bearing diagnostics - a
tutorial", MSSP 25, 2011, sections 2 and 3; McFadden & Smith 1984):
  inner  impulses at BPFI, amplitude modulated at the shaft rate fr (the defect turns through
         the load zone once per shaft turn)
  outer  impulses at BPFO, unmodulated (the defect stands still in the load zone)
  ball   impulses at 2 BSF (the spall strikes both races once per spin turn), amplitude
         modulated at the cage rate FTF (the ball carries load only while the cage takes it
         through the load zone, once per cage turn)
each impulse ringing a structural resonance (a decaying sine), the interval between impulses
jittered by a random slip of 1-2 %, plus the shaft harmonics (unbalance, misalignment) and
Gaussian noise at a given SNR (impulse train power over noise power in dB).
"""
import math

import numpy as np

# CWRU rig bearings (CWRU Bearing Data Center, "Bearing information"; the catalog files
# inputs/bearings/6205-2RS_JEM and 6203-2RS_JEM): balls, ball and pitch diameters (inches);
# "close": a bearing whose 2 BSF lies 1 % from its BPFO (Z = 10, d/D = 0.247: 2 BSF / BPFO =
# 2 (1 + d/D) / (Z d/D)), where the ball and outer-race combs claim the same lines
GEOMETRY = {"6205-2RS_JEM": (9, 0.3126, 1.537), "6203-2RS_JEM": (8, 0.2656, 1.122),
            "close": (10, 0.247, 1.0)}


def bearing_args(bearing):
    """diagnose's options for the bearing: the catalog name, or Z, d and D for "close"."""
    if bearing != "close":
        return ["--bearing", bearing]
    nb, d, dp = GEOMETRY[bearing]
    return ["--nb", str(nb), "--db", repr(d * 0.01), "--dp", repr(dp * 0.01), "--beta", "0"]


def defect_orders(bearing):
    """Kinematic defect frequencies in shaft orders (no contact angle): bpfi, bpfo, bsf, ftf."""
    nb, d, dp = GEOMETRY[bearing]
    r = d / dp
    return {"bpfi": nb / 2 * (1 + r), "bpfo": nb / 2 * (1 - r), "bsf": dp / (2 * d) * (1 - r * r),
            "ftf": 0.5 * (1 - r)}


def signal(kind, bearing, fr, rate, duration, snr_db, seed, resonance_hz=None, slip=0.015,
           hit_fraction=1.0):
    """One record of `kind` (inner, outer, ball or none) for `bearing` at shaft rate fr (Hz);
    hit_fraction < 1: each impulse happens with that probability (a ball's spall leaving the
    contact path as its spin axis wanders: a less periodic train)."""
    rng = np.random.default_rng(seed)
    n = int(round(duration * rate))
    t = np.arange(n) / rate
    o = defect_orders(bearing)
    x = np.zeros(n)
    if kind != "none":
        f_imp = {"inner": o["bpfi"], "outer": o["bpfo"], "ball": 2 * o["bsf"]}[kind] * fr
        # impulse times: mean period 1/f_imp, each interval jittered by the slip (uniform
        # +-slip around the mean, so that the pulse train is not exactly periodic)
        times = []
        tk = rng.uniform(0, 1 / f_imp)
        while tk < duration:
            times.append(tk)
            tk += (1 + rng.uniform(-slip, slip)) / f_imp
        times = np.array(times)
        if hit_fraction < 1:
            times = times[rng.uniform(0, 1, len(times)) < hit_fraction]
        if kind == "inner":
            amp = 0.6 + 0.4 * np.cos(2 * math.pi * fr * times)
        elif kind == "ball":
            # load zone: the ball is loaded over half a cage turn (a raised cosine window)
            phase = 2 * math.pi * o["ftf"] * fr * times + rng.uniform(0, 2 * math.pi)
            amp = np.maximum(np.cos(phase), 0.0) ** 1.5
        else:
            amp = np.ones_like(times)
        amp = amp * (1 + 0.1 * rng.standard_normal(len(times)))  # impact-to-impact scatter
        fn = resonance_hz or min(3000.0, 0.25 * rate)
        zeta = 0.05
        wd = 2 * math.pi * fn * math.sqrt(1 - zeta * zeta)
        L = int(8 / (zeta * 2 * math.pi * fn) * rate)  # 8 time constants
        tau = np.arange(L) / rate
        ring = np.exp(-zeta * 2 * math.pi * fn * tau) * np.sin(wd * tau)
        idx = np.floor(times * rate).astype(int)
        frac = times * rate - idx
        # fractional delays: spread each impulse on its two neighbouring samples
        for i0, fr_, a in zip(idx, frac, amp):
            for j, w in ((i0, 1 - fr_), (i0 + 1, fr_)):
                if j < n:
                    m = min(L, n - j)
                    x[j:j + m] += a * w * ring[:m]
    p_sig = np.mean(x ** 2) if kind != "none" else 1.0
    noise = rng.standard_normal(n) * math.sqrt(p_sig / 10 ** (snr_db / 10))
    # shaft harmonics at 1 and 2 fr, each as strong as the impulse train's RMS
    shaft = math.sqrt(p_sig) * (np.sin(2 * math.pi * fr * t + 0.3) +
                                0.5 * np.sin(4 * math.pi * fr * t + 1.1))
    return x + noise + shaft


def write_npy(path, x):
    np.save(path, x.astype(np.float64))

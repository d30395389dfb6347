#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The accelerometer's model curve: the energy of the ring's response to one defect
pass, averaged over the passes (`ohmdem-post diagnose --size-method accel-curve`, JSON
pass_energy_v2s), against the pit's size, from short runs of the sizing study's scene (the 6208
at 500 rad/s, radial load, pits 50 um deep at the load zone's centre) passed through the record's
own accelerometer chain (studies/sizing.py, acquire_acc: 10 mV/g, +-5 V, 16 bits, the rate's anti-alias
filter, the noise level). The curve is cut where the energy stops increasing; its own error is
the RMS relative deviation of the energy of runs at sizes the curve does not use (diagnose
--size-model-error).
  studies/accel_curve.py [--rates 1e4,2e4,5e4] [--noise low,high] OUT
Writes OUT/accel_curve_<defect>_r<rate>_<noise>.txt (the curves, the error in their header) and
prints them; studies/sizing_map.py calls model_curve for its 'acc-curve' channel.
"""
import argparse
import json
import math
import os
import sys

import common
import sizing

# the curve's sizes (0.15 s runs) and the error runs' are the sizing study's: no case uses them
CURVE_SIZES = sizing.CURVE_SIZES
ERROR_SIZES = sizing.ERROR_SIZES


def energy(out, defect, size, rate, noise, tend=sizing.T_FROM + 0.15):
    """The mean pass energy (V^2 s) of a run of the scene through the accelerometer chain."""
    sim = sizing.simulate(out, (defect, size, "radial", 90.0), tend)
    acq = os.path.join(out, "acq", f"acc_{defect}_{size:g}_r{rate:g}_{noise}.txt")
    if not os.path.exists(acq):
        sizing.acquire_acc(sim, rate, noise, acq)
    r = common.post(["diagnose", "--format", "json", "--column", "V", "--metadata",
                     os.path.join(sim, "run.json"), "--from", repr(sizing.T_FROM),
                     "--assume-defect", defect, "--size-method", "accel-curve", acq],
                    who="accel_curve")
    return json.loads(r.stdout).get("pass_energy_v2s")


def energy_at(rows, size):
    """The curve's energy at a size within it (the same power law)."""
    k = next(i for i in range(1, len(rows)) if size <= rows[i][0])
    (s0, e0), (s1, e1) = rows[k - 1], rows[k]
    p = math.log(e1 / e0) / math.log(s1 / s0)
    return e0 * (size / s0) ** p


def model_curve(out, defect, rate, noise):
    """(path, rows, error): the curve through the chain at (rate, noise), its own error."""
    rows = []
    for size in CURVE_SIZES:
        e = energy(out, defect, size, rate, noise)
        if e is None or e <= 0 or (rows and e <= rows[-1][1]):
            break
        rows.append((size, e))
    dev = [energy(out, defect, s, rate, noise) / energy_at(rows, s) - 1
           for s in ERROR_SIZES if len(rows) > 1 and rows[0][0] <= s <= rows[-1][0]]
    err = (sum(d * d for d in dev) / len(dev)) ** 0.5 if dev else None
    path = os.path.join(out, f"accel_curve_{defect}_r{rate:g}_{noise}.txt")
    sizing.write_curve(path, f"{defect} defect, radial load, accelerometer r{rate:g} {noise}: "
                       "size_deg, pass energy (V^2 s)",
                       f"the energy at {sizing.sizes_text(ERROR_SIZES)} deg", err,
                       "--size-model-error", rows)
    return path, rows, err


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rates", default="1e4,2e4,5e4")
    ap.add_argument("--noise", default="low,high")
    ap.add_argument("out")
    a = ap.parse_args(argv)
    try:
        rates = [float(r) for r in a.rates.split(",")]
    except ValueError:
        sys.exit("accel_curve: --rates takes numbers (Hz) separated by commas, got " + a.rates)
    noises = a.noise.split(",")
    if not set(noises) <= set(sizing.ACC_NOISE):
        sys.exit("accel_curve: --noise takes low, mid and/or high, got " + a.noise)
    out = os.path.abspath(a.out)
    os.makedirs(os.path.join(out, "acq"), exist_ok=True)
    for defect in ("inner", "outer"):
        for rate in rates:
            for noise in noises:
                path, rows, err = model_curve(out, defect, rate, noise)
                print(f"{defect} {rate:g} Hz {noise}: " +
                      ", ".join(f"{s:g} deg {e:.3g}" for s, e in rows) +
                      f"; error {'-' if err is None else format(err, '.3f')} ({path})")


if __name__ == "__main__":
    main(sys.argv[1:])

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""An outer-race pit's angle from the load direction from a two-axis accelerometer
(`ohmdem-post diagnose --across-column`, bearing/event_direction.h): a ball entering or leaving
the pit changes its push on the ring along the pit's radius, so the defect events' acceleration
in the bearing's plane points along it. Outer pits of the sizing study's scene (the 6208 at 500
rad/s, radial load, 50 um deep) at places from the load direction, both ring axes (the deck's
acc_along and acc_across) through the accelerometer chain of studies/sizing.py (acquire_acc) (10 mV/g,
+-5 V, 16 bits, anti-alias filter 0.4 x rate, the two noise levels; each axis its own noise
seed) in one record (`acquire --across-column`), diagnosed with `--size-method accel-curve
--across-column V2` on the committed outer curves (doc/report/detectability/accel_curves/).

Two sets: 'tuning', the cases whose largest error set the method's allowance for the ring's
response (EventDirectionSettings::model_deg), and 'held-out', sizes and places not used for it.
One held-out place lies beyond the load zone (100 deg), where the balls' centrifugal force alone
presses the ring: the events' line is found there too, but the angle is given on the load zone's
side, 180 deg off (the table gives its error as a line's, modulo 180 deg).

  studies/accel_outer_angle.py [--tiny] OUT

--tiny: one held-out case (1 deg, 25 deg from the load) at 20 kHz, low noise (the test). Writes
OUT/accel_outer_angle.csv and OUT/accel_outer_angle.md (doc/report/detectability/).
"""
import argparse
import json
import os
import sys

import common
import sizing

CURVES = os.path.join(common.DOC, "report", "detectability", "accel_curves")
BEYOND_ZONE = 100.0  # deg from the load: outside the load zone


def grid(tiny):
    if tiny:
        return {"sets": {"held-out": [(1.0, 25.0)]}, "rates": [2e4], "noise": ["low"]}
    return {"sets": {"tuning": [(s, d) for s in (0.3, 1.0, 3.0) for d in (0.0, 15.0, -30.0, 45.0)],
                     "held-out": [(s, d) for s in (0.5, 2.0)
                                  for d in (-10.0, 25.0, -40.0, 55.0, BEYOND_ZONE)]},
            "rates": [1e4, 2e4, 5e4], "noise": ["low", "high"]}


def acquire(sim, rate, noise, dest):
    """Both ring axes through the sizing map's chain into one record (time V V2)."""
    return dest if os.path.exists(dest) else sizing.acquire_acc(sim, rate, noise, dest,
                                                                   across=True)


def one(out, which, size, offset, rate, noise):
    sim = sizing.simulate(out, ("outer", size, "radial", 90.0 + offset),
                          sizing.T_FROM + sizing.WINDOW)
    acq = acquire(sim, rate, noise, os.path.join(
        out, "acq", f"acc2_outer_{size:g}_d{offset:g}_r{rate:g}_{noise}.txt"))
    args = ["diagnose", "--format", "json", "--column", "V", "--across-column", "V2",
            "--metadata", os.path.join(sim, "run.json"), "--from", repr(sizing.T_FROM),
            "--assume-defect", "outer", "--size-method", "accel-curve"]
    curve = os.path.join(CURVES, f"accel_curve_outer_r{rate:g}_{noise}.txt")
    if os.path.exists(curve):
        args += ["--size-curve", curve]
    d = json.loads(common.post(args + [acq], who="accel_outer_angle").stdout)
    pos, iv = d.get("position_deg"), d.get("position_interval_deg")
    # beyond the zone the angle is read on the zone's side: its error as a line's
    truth = offset if offset != BEYOND_ZONE else offset - 180
    err = None if pos is None else pos - truth
    covers = iv is not None and iv[0] <= truth <= iv[1]
    return {"set": which, "size_deg": size, "offset_deg": offset, "rate_hz": rate, "noise": noise,
            "position_deg": pos, "low": iv[0] if iv else None, "high": iv[1] if iv else None,
            "error_deg": err, "covers": covers,
            "note": str(d.get("position_note", "")).replace(",", ";")}


def summary(rows, g, which):
    lines = ["| noise | " + " | ".join(f"{r / 1e3:g} kHz" for r in g["rates"]) + " |",
             "|---" * (len(g["rates"]) + 1) + "|"]
    for noise in g["noise"]:
        cells = []
        for rate in g["rates"]:
            rs = [r for r in rows if r["set"] == which and r["rate_hz"] == rate
                  and r["noise"] == noise and r["offset_deg"] != BEYOND_ZONE]
            e = sorted(abs(r["error_deg"]) for r in rs if r["error_deg"] is not None)
            cells.append(f"{len(e)}/{len(rs)}, " + (f"{e[len(e) // 2]:.1f} / {e[-1]:.1f}" if e
                                                    else "-")
                         + f", {sum(r['covers'] for r in rs)} of {len(rs)}")
        lines.append(f"| {noise} | " + " | ".join(cells) + " |")
    return lines


def write(out, rows, g, tiny):
    common.write_csv(os.path.join(out, "accel_outer_angle.csv"), rows)
    lines = ["# An outer pit's angle from a two-axis accelerometer", "",
             f"Regenerated at {common.made_at()} by `studies/accel_outer_angle.py {'--tiny ' if tiny else ''}OUT`. The "
             "sizing study's scene (the 6208 at 500 rad/s, radial load, outer pits 50 um deep at "
             "the given angle from the load direction), both ring axes through the accelerometer "
             "of the sizing map (10 mV/g, 16 bits, noise 5e-5 and 5e-3 m/s^2/sqrt(Hz), each axis "
             "its own noise); `diagnose --size-method accel-curve --across-column V2`. Cells: "
             "placed / cases in the load zone, median and largest |error| (deg), intervals "
             "holding the angle."]
    for which in g["sets"]:
        lines += ["", f"## {which}", ""] + summary(rows, g, which)
    lines += ["", "| set | size (deg) | from the load (deg) | rate | noise | placed (deg) | "
              "interval | error (deg; at 100, the line's) | note |", "|---" * 9 + "|"]
    for r in rows:
        iv = "-" if r["low"] is None else f"[{r['low']:.1f}, {r['high']:.1f}]"
        lines.append(
            f"| {r['set']} | {r['size_deg']:g} | {r['offset_deg']:g} | {r['rate_hz'] / 1e3:g} kHz"
            f" | {r['noise']} | "
            + ("-" if r["position_deg"] is None else f"{r['position_deg']:.1f}")
            + f" | {iv} | " + ("-" if r["error_deg"] is None else f"{r['error_deg']:+.1f}")
            + " | " + (r["note"] if r["position_deg"] is None else "") + " |")
    zone = [r for r in rows if r["offset_deg"] != BEYOND_ZONE]
    placed = [r for r in zone if r["error_deg"] is not None]
    beyond = [r for r in rows if r["offset_deg"] == BEYOND_ZONE]
    lines += ["", f"In the load zone: placed {len(placed)}/{len(zone)}; within 15 deg: "
              f"{sum(abs(r['error_deg']) <= 15 for r in placed)}/{len(zone)}; intervals holding "
              f"the angle: {sum(r['covers'] for r in zone)}/{len(zone)}."
              + (f" Beyond the load zone ({BEYOND_ZONE:g} deg from the load): the line placed "
                 f"in {sum(r['error_deg'] is not None for r in beyond)}/{len(beyond)}, within 15 "
                 f"deg of it in "
                 f"{sum(r['error_deg'] is not None and abs(r['error_deg']) <= 15 for r in beyond)}"
                 f"/{len(beyond)}, read 180 deg off (on the zone's side) as documented."
                 if beyond else "")]
    with open(os.path.join(out, "accel_outer_angle.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tiny", action="store_true", help="one case at 20 kHz (the test)")
    ap.add_argument("out")
    a = ap.parse_args(argv)
    out = os.path.abspath(a.out)
    os.makedirs(os.path.join(out, "acq"), exist_ok=True)
    g = grid(a.tiny)
    rows = []
    for which, cases in g["sets"].items():
        for size, offset in cases:
            for rate in g["rates"]:
                for noise in g["noise"]:
                    rows.append(one(out, which, size, offset, rate, noise))
                    print(rows[-1], flush=True)
    write(out, rows, g, a.tiny)


if __name__ == "__main__":
    main(sys.argv[1:])

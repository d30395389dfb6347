#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""An inner-race pit's place on the ring from a record with a shaft angle, from an
accelerometer (`ohmdem-post diagnose --size-method accel-curve`, bearing/pass_energy.h) or from
the electrical channel (the pulse area, bearing/pulse_area.h): under the radial load the passes'
energy, or their pulses' area, peaks when the pit meets the load direction, so that against the
shaft angle at each pass gives the pit's angle from the shaft's zero. Inner pits of the sizing
study's scene (the 6208 at 500 rad/s, radial load, 50 um deep) at ring places none of the
methods' checks used, with the deck's shaft angle as a column (angle_inner):
- acc: through the accelerometer chain of studies/sizing.py (acquire_acc) (10 mV/g, +-5 V, 16 bits,
  anti-alias filter 0.4 x rate, the two noise levels), sized on the committed model curves
  (doc/report/detectability/accel_curves/);
- electrical: through the sizing study's R chain (studies/sizing.py), sized on its chain curves
  (made under OUT by sizing.model_curve; --tiny: the committed 20 kHz low-noise curve in
  doc/report/sizing/).

  studies/accel_position.py [--tiny] [--channel acc|electrical] [--cases S:P,...] OUT

--tiny: one case (1 deg at 135 deg) at 20 kHz, low noise (the test). Writes OUT/accel_position.csv
and .md (acc) or OUT/electrical_position.csv and .md (doc/report/detectability/).
"""
import argparse
import json
import os
import sys

import common
import sizing

CURVES = os.path.join(common.DOC, "report", "detectability", "accel_curves")


def grid(tiny, cases=None):
    if tiny:
        return {"cases": [(1.0, 135.0)], "rates": [2e4], "noise": ["low"]}
    if cases:
        cases = [tuple(float(v) for v in c.split(":")) for c in cases.split(",")]
    else:
        cases = [(s, p) for s in (0.3, 1.0, 2.0, 3.0) for p in (15.0, 160.0, 250.0, 300.0)]
    return {"cases": cases, "rates": [1e4, 2e4, 5e4], "noise": ["low", "high"]}


def curve_error(path):
    """The curve's own error as its header gives it to diagnose (sizing.write_curve), or None."""
    with open(path) as f:
        for line in f:
            if line.startswith("#") and "--size-model-error " in line:
                return line.split("--size-model-error ")[1].split()[0]
    return None


def acquire(sim, rate, noise, dest):
    """The accelerometer record with the deck's shaft angle (omega t) as a second column."""
    if os.path.exists(dest):
        return dest
    tmp = dest + ".acc"
    sizing.acquire_acc(sim, rate, noise, tmp)
    sizing.with_angle(tmp, dest)
    return dest


def electrical_curve(out, rate, noise, tiny, curves):
    """The chain curve of the electrical channel (sizing.model_curve, once per rate and noise);
    tiny: the committed one."""
    if tiny:
        return os.path.join(common.DOC, "report", "sizing",
                            f"curve_inner_radial_r{rate:g}_{noise}.txt")
    if (rate, noise) not in curves:
        curves[rate, noise] = sizing.model_curve(out, "inner", "radial", rate, noise)[0]
    return curves[rate, noise]


def one(out, size, place, rate, noise, channel="acc", tiny=False, curves=None):
    sim = sizing.simulate(out, ("inner", size, "radial", place), sizing.T_FROM + sizing.WINDOW)
    name = f"{channel}_inner_{size:g}_p{place:g}_r{rate:g}_{noise}.txt"
    args = ["diagnose", "--format", "json", "--column", "V", "--metadata",
            os.path.join(sim, "run.json"), "--from", repr(sizing.T_FROM), "--assume-defect",
            "inner"]
    if channel == "acc":
        acq = acquire(sim, rate, noise, os.path.join(out, "acq", name))
        curve = os.path.join(CURVES, f"accel_curve_inner_r{rate:g}_{noise}.txt")
        args += ["--size-method", "accel-curve"]
    else:
        acq = os.path.join(out, "acq", name)
        if not os.path.exists(acq):
            sizing.acquire_with_angle(sim, "radial", rate, noise, acq)
        curve = electrical_curve(out, rate, noise, tiny, curves if curves is not None else {})
    if os.path.exists(curve):
        args += ["--size-curve", curve]
        err = curve_error(curve)
        if err:
            args += ["--size-model-error", err]
    d = json.loads(common.post(args + [acq], who="accel_position").stdout)
    pos, iv = d.get("position_deg"), d.get("position_interval_deg")
    err = None if pos is None else (pos - place + 180) % 360 - 180
    covers = iv is not None and ((iv[0] - place + 180) % 360 - 180) <= 0 <= \
        ((iv[1] - place + 180) % 360 - 180)
    size_est, siv = d.get("size_deg"), d.get("size_interval_deg")
    return {"size_deg": size, "place_deg": place, "rate_hz": rate, "noise": noise,
            "position_deg": pos, "low": iv[0] if iv else None, "high": iv[1] if iv else None,
            "error_deg": err, "covers": covers, "size_est_deg": size_est if siv else None,
            "size_error_pct": None if not siv else 100 * (size_est / size - 1),
            "note": str(d.get("position_note", "")).replace(",", ";")}


CHAINS = {
    "acc": ("the accelerometer", "the accelerometer of the sizing map (10 mV/g, 16 bits, noise "
            "5e-5 and 5e-3 m/s^2/sqrt(Hz)) with the deck's shaft angle; `diagnose --size-method "
            "accel-curve` on the committed curves"),
    "electrical": ("the electrical channel", "the sizing study's R chain (0.1 A, 16 bits, "
                   "anti-alias filter 0.4 x rate, its two noise levels) with the deck's shaft "
                   "angle; `diagnose` (the pulse area) on the chain curves of studies/sizing.py"),
}


def stem(channel):
    return "accel_position" if channel == "acc" else "electrical_position"


def write(out, rows, g, tiny, channel="acc", cases=None):
    common.write_csv(os.path.join(out, stem(channel) + ".csv"), rows)
    title, chain = CHAINS[channel]
    flags = ("--tiny " if tiny else "") + ("" if channel == "acc" else f"--channel {channel} ")
    if cases:
        flags += f"--cases {cases} "
    lines = [f"# An inner pit's place from {title}", "",
             f"Regenerated at {common.made_at()} by `studies/accel_position.py {flags}OUT`. The "
             "sizing study's scene (the 6208 at 500 rad/s, radial load along +y, inner pits 50 um "
             f"deep), {chain}. Cells: placed / cases, median and largest |error| (deg), "
             "intervals holding the place.", "",
             "| noise | " + " | ".join(f"{r / 1e3:g} kHz" for r in g["rates"]) + " |",
             "|---" * (len(g["rates"]) + 1) + "|"]
    for noise in g["noise"]:
        cells = []
        for rate in g["rates"]:
            rs = [r for r in rows if r["rate_hz"] == rate and r["noise"] == noise]
            e = sorted(abs(r["error_deg"]) for r in rs if r["error_deg"] is not None)
            cells.append(f"{len(e)}/{len(rs)}, " + (f"{e[len(e) // 2]:.1f} / {e[-1]:.1f}" if e
                                                    else "-")
                         + f", {sum(r['covers'] for r in rs)} of {len(rs)}")
        lines.append(f"| {noise} | " + " | ".join(cells) + " |")
    lines += ["", "| size (deg) | place (deg) | rate | noise | placed (deg) | interval | error "
              "(deg) | size read (deg) |", "|---" * 8 + "|"]
    for r in rows:
        iv = "-" if r["low"] is None else f"[{r['low']:.1f}, {r['high']:.1f}]"
        lines.append(
            f"| {r['size_deg']:g} | {r['place_deg']:g} | {r['rate_hz'] / 1e3:g} kHz | "
            f"{r['noise']} | " + ("-" if r["position_deg"] is None else f"{r['position_deg']:.1f}")
            + f" | {iv} | " + ("-" if r["error_deg"] is None else f"{r['error_deg']:+.1f}")
            + " | " + ("-" if r["size_est_deg"] is None else f"{r['size_est_deg']:.2f}") + " |")
    placed = [r for r in rows if r["error_deg"] is not None]
    lines += ["", f"Placed {len(placed)}/{len(rows)}; within 10 deg: "
              f"{sum(abs(r['error_deg']) <= 10 for r in placed)}/{len(rows)}; intervals holding "
              f"the place: {sum(r['covers'] for r in rows)}/{len(rows)}."]
    with open(os.path.join(out, stem(channel) + ".md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tiny", action="store_true", help="one case at 20 kHz (the test)")
    ap.add_argument("--channel", choices=sorted(CHAINS), default="acc")
    ap.add_argument("--cases", help="SIZE:PLACE pairs (deg of pit, deg on the ring), comma "
                    "separated, instead of the study's 16")
    ap.add_argument("out")
    a = ap.parse_args(argv)
    out = os.path.abspath(a.out)
    os.makedirs(os.path.join(out, "acq"), exist_ok=True)
    g = grid(a.tiny, a.cases)
    rows, curves = [], {}
    for size, place in g["cases"]:
        for rate in g["rates"]:
            for noise in g["noise"]:
                rows.append(one(out, size, place, rate, noise, a.channel, a.tiny, curves))
                print(rows[-1], flush=True)
    write(out, rows, g, a.tiny, a.channel, a.cases)


if __name__ == "__main__":
    main(sys.argv[1:])

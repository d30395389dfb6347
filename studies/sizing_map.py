#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The sizing map: the error of `ohmdem-post diagnose`'s defect size against the
instrument's sampling rate and noise, per channel, for the detectability study's report.

The scene is the sizing study's (studies/sizing.py: the 6208 at 500 rad/s under the radial load,
pits 50 um deep at the load zone's centre). Channels:
  electrical  V = I R through the detectability study's electrical chain, sized by the pulse
              area on the model's curve through the same chain (diagnose --size-curve, the
              'chain curve' of the sizing study, with its own error)
  acc         the outer ring's acceleration along the load through an accelerometer, sized by
              the double-impulse method (diagnose --size-method double-impulse): the delay
              between the ball's entry and exit events in the pit
  acc-curve   the same record sized by the passes' energy on the model's curve through the same
              chain (diagnose --size-method accel-curve; studies/accel_curve.py), with its own error
  template    the electrical channel's record sized by its pulse's shape (diagnose --size-method
              template) on the bank for its chain, bank_<defect>_radial_r<rate>_<noise>.txt in
              --template-banks DIR (default: the committed ones, low noise: both pits at 20 kHz,
              the outer pit at 10 and 50 kHz; a chain without a bank has no cell:
              studies/template_bank.py makes one)
Each case is acquired at every rate (16 bits) and noise level of the grid and diagnosed with
--assume-defect (the map measures the sizing, not the identification).
  studies/sizing_map.py [--tiny] [--channels electrical,acc,acc-curve,template]
                        [--template-banks DIR] [--report-only] OUT
Writes OUT/sizing_map.csv (one row per case, channel, rate and noise), OUT/sizing_map.md (the
tables) and OUT/sizing_map_<channel>.png (median |error| against rate and noise: a heatmap).
--tiny: one case (outer 3 deg), 20 and 50 kHz, low noise, the accelerometer and the template
(the test).
"""
import argparse
import json
import os
import subprocess
import sys

import accel_curve
import common
import sizing

CHANNELS = ("electrical", "acc", "acc-curve", "template")
BANKS = os.path.join(common.DOC, "report", "sizing", "template")


def grid(tiny):
    if tiny:
        return {"cases": [("outer", 3.0)], "rates": [2e4, 5e4], "noise": ["low"],
                "channels": ["acc", "template"]}
    return {"cases": [(d, s) for d in ("inner", "outer") for s in (0.3, 1.0, 2.0, 3.0)],
            "rates": [1e4, 1.2e4, 2e4, 4.8e4, 5e4], "noise": ["low", "high"],
            "channels": list(CHANNELS)}


def bank_of(banks, defect, rate, noise):
    """The template bank for the chain in the folder banks, or None."""
    path = os.path.join(banks, f"bank_{defect}_radial_r{rate:g}_{noise}.txt")
    return path if os.path.exists(path) else None


def diagnose(sim, acq, defect, extra):
    r = common.post(["diagnose", "--format", "json", "--column", "V", "--metadata",
                     os.path.join(sim, "run.json"), "--from", repr(sizing.T_FROM),
                     "--assume-defect", defect] + extra + [acq], who="sizing_map",
                    allow_fail=True)
    return json.loads(r.stdout) if r.returncode == 0 else {"size_method": r.stderr.strip()}


def one(out, case, channel, rate, noise, curves, bank=None):
    """The case through the channel's chain, sized; bank: the template channel's bank."""
    defect, size = case
    sim = sizing.simulate(out, (defect, size, "radial", 90.0), sizing.T_FROM + sizing.WINDOW)
    # the template channel sizes the electrical channel's record: acquired once for both
    record = "electrical" if channel == "template" else channel
    acq = os.path.join(out, "acq", f"{record}_{defect}_{size:g}_r{rate:g}_{noise}.txt")
    if record == "electrical" and not os.path.exists(acq):
        sizing.acquire_with_angle(sim, "radial", rate, noise, acq)
    if channel == "template":
        d = diagnose(sim, acq, defect, ["--size-method", "template", "--template-bank", bank])
    elif channel == "acc":
        d = diagnose(sim, sizing.acquire_acc(sim, rate, noise, acq), defect,
                     ["--size-method", "double-impulse"])
    elif channel == "acc-curve":
        key = (channel, defect, rate, noise)
        if key not in curves:
            curves[key] = accel_curve.model_curve(out, defect, rate, noise)
        extra = ["--size-method", "accel-curve", "--size-curve", curves[key][0]]
        if curves[key][2]:
            extra += ["--size-model-error", repr(curves[key][2])]
        d = diagnose(sim, sizing.acquire_acc(sim, rate, noise, acq), defect, extra)
    else:
        key = (defect, rate, noise)
        if key not in curves:
            curves[key] = sizing.model_curve(out, defect, "radial", rate, noise)
        extra = ["--size-curve", curves[key][0]]
        if curves[key][2]:
            extra += ["--size-model-error", repr(curves[key][2])]
        d = diagnose(sim, acq, defect, extra)
    iv = d.get("size_interval_deg")
    est = d.get("size_deg") if iv else None  # a size without interval is the pulse width's
    covers = est is not None and iv[0] <= size and (iv[1] is None or size <= iv[1])
    return {"channel": channel, "defect": defect, "size_deg": size, "rate_hz": rate,
            "noise": noise, "size_est_deg": est, "low": iv[0] if iv else None,
            "high": iv[1] if iv else None,
            "error_pct": None if est is None else 100 * (est / size - 1), "covers": covers,
            "note": "" if est is not None else str(d.get("size_method", "")).replace(",", ";")}


def median_abs(rs):
    e = sorted(abs(r["error_pct"]) for r in rs if r["error_pct"] is not None)
    return e[len(e) // 2] if e else None


def heatmap(out, rows, g, channel):
    """Median |error| (%) over the cases, rate x noise, a case not sized counting as 100 %
    (capped there); no cell where the channel was not acquired at that rate."""
    dat = os.path.join(out, f"sizing_map_{channel}.dat")
    with open(dat, "w") as f:
        for j, noise in enumerate(g["noise"]):
            for i, rate in enumerate(g["rates"]):
                rs = [r for r in rows if r["channel"] == channel and r["rate_hz"] == rate and
                      r["noise"] == noise]
                if rs:
                    e = sorted(100 if r["error_pct"] is None else min(abs(r["error_pct"]), 100)
                               for r in rs)
                    f.write(f"{i} {j} {e[len(e) // 2]:.3f}\n")
            f.write("\n")
    png = os.path.join(out, f"sizing_map_{channel}.png")
    xt = ", ".join(f"'{r / 1e3:g} kHz' {i}" for i, r in enumerate(g["rates"]))
    yt = ", ".join(f"'{n}' {j}" for j, n in enumerate(g["noise"]))
    script = (f"set terminal pngcairo size 800,{250 + 60 * len(g['noise'])}; set output '{png}'; "
              f"set xtics ({xt}); set ytics ({yt}); set cbrange [0:100]; "
              "set cblabel 'median |size error| (%)'; "
              "set palette defined (0 'white', 15 'yellow', 50 'orange', 100 'red'); "
              f"set xlabel 'sampling rate'; set ylabel 'noise'; set title '{channel}: size error "
              "against rate and noise'; "
              f"set xrange [-0.5:{len(g['rates']) - 0.5}]; set yrange [-0.5:{len(g['noise']) - 0.5}]; "
              f"plot '{dat}' using 1:2:3 with points pt 5 ps 9 palette notitle, '{dat}' using "
              "1:2:(sprintf('%.0f', $3)) with labels notitle")
    subprocess.run(["gnuplot", "-e", script], check=True)
    return png


def table(rows, g):
    lines = ["| channel | noise | " + " | ".join(f"{r / 1e3:g} kHz" for r in g["rates"]) + " |",
             "|---|---|" + "---|" * len(g["rates"])]
    for channel in g["channels"]:
        for noise in g["noise"]:
            cells = []
            for rate in g["rates"]:
                rs = [r for r in rows if r["channel"] == channel and r["rate_hz"] == rate and
                      r["noise"] == noise]
                sized = [r for r in rs if r["error_pct"] is not None]
                m = median_abs(rs)
                big = max((abs(r["error_pct"]) for r in sized), default=None)
                cells.append("-" if not rs else f"{len(sized)}/{len(rs)} sized" +
                             ("" if m is None else f", {m:.0f} % / {big:.0f} %, covers "
                              f"{sum(r['covers'] for r in rs)}"))
            lines.append(f"| {channel} | {noise} | " + " | ".join(cells) + " |")
    return lines


def per_case(rows, g, channel):
    lines = ["| defect | size (deg) | " + " | ".join(f"{r / 1e3:g} kHz" for r in g["rates"]) +
             " |", "|---|---|" + "---|" * len(g["rates"])]
    for defect, size in g["cases"]:
        for noise in g["noise"]:
            cells = []
            for rate in g["rates"]:
                r = next((r for r in rows if r["channel"] == channel and r["defect"] == defect
                          and r["size_deg"] == size and r["rate_hz"] == rate and
                          r["noise"] == noise), None)
                cells.append("-" if r is None or r["size_est_deg"] is None else
                             f"{r['size_est_deg']:.2f} [{r['low']:.2f}, "
                             f"{'open' if r['high'] is None else format(r['high'], '.2f')}]")
            lines.append(f"| {defect} | {size:g} ({noise}) | " + " | ".join(cells) + " |")
    return lines


def run(out, tiny=False, channels=None, banks=BANKS):
    g = grid(tiny)
    if channels:
        g["channels"] = channels
    os.makedirs(os.path.join(out, "acq"), exist_ok=True)
    rows, curves = [], {}
    for channel in g["channels"]:
        rates = g["rates"] if channel == "acc" else [r for r in g["rates"] if r in sizing.RATES]
        for case in g["cases"]:
            for rate in rates:
                for noise in g["noise"]:
                    bank = bank_of(banks, case[0], rate, noise) if channel == "template" \
                        else None
                    if channel == "template" and not bank:
                        continue  # no bank for this chain: no cell
                    rows.append(one(out, case, channel, rate, noise, curves, bank))
    write(out, rows, g, tiny)
    return rows


def read_rows(path):
    """OUT/sizing_map.csv back as rows (--report-only)."""
    import csv
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            for k in ("size_deg", "rate_hz", "size_est_deg", "low", "high", "error_pct"):
                r[k] = float(r[k]) if r[k] else None
            r["covers"] = r["covers"] == "True"
            rows.append(r)
    return rows


def write(out, rows, g, tiny):
    """sizing_map.csv, the heatmaps and sizing_map.md."""
    common.write_csv(os.path.join(out, "sizing_map.csv"), rows)
    pngs = [heatmap(out, rows, g, c) for c in g["channels"]]
    lines = ["# Sizing map", "",
             f"Regenerated at {common.made_at()} by `studies/sizing_map.py {'--tiny ' if tiny else ''}OUT` (called by "
             "`studies/detectability.py`). The sizing study's scene: the 6208 at 500 rad/s, "
             "radial load, pits 50 um deep at the load zone's centre, sizes " +
             ", ".join(f"{d} {s:g} deg" for d, s in g["cases"]) + "; 16 bits. Cells: cases "
             "sized / cases, median / largest |size error| of those sized, intervals covering the "
             "true size (of all the cases). A case not sized is not covered. The electrical channel is "
             "R as the instrument records it, the voltage I R (one channel: R and the voltage "
             "differ by the current only); the lubricated model's Cb is not mapped (the area "
             "method is written for R's jumps). The template channel is the same electrical "
             "record sized by its pulse's shape on a bank of simulated folds through its chain, "
             "where a bank was given (the committed ones, low noise: both pits at 20 kHz, the "
             "outer pit at 10 and 50 kHz; at every chain, with banks made for it, the same "
             "records' template fits are in ../sizing/template/template_tables.md).", ""]
    lines += table(rows, g) + [""]
    for c in g["channels"]:
        lines += [f"Per case, {c} (estimate [interval], deg):", ""] + per_case(rows, g, c) + [""]
    lines += ["The figures: the median |size error| over all the cases, a case not sized counting "
              "as 100 %.", ""]
    lines += [f"![{os.path.basename(p)}]({os.path.basename(p)})" for p in pngs]
    with open(os.path.join(out, "sizing_map.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tiny", action="store_true", help="one case, two rates (the test)")
    ap.add_argument("--channels",
                    help="comma-separated subset of electrical,acc,acc-curve,template")
    ap.add_argument("--template-banks", default=BANKS,
                    help="folder of bank_<defect>_radial_r<rate>_<noise>.txt (default: the "
                    "committed banks)")
    ap.add_argument("--report-only", action="store_true",
                    help="rewrite the tables and figures from OUT/sizing_map.csv")
    ap.add_argument("out")
    a = ap.parse_args(argv)
    channels = a.channels.split(",") if a.channels else None
    if channels and not set(channels) <= set(CHANNELS):
        sys.exit("sizing_map: --channels takes electrical, acc, acc-curve and/or template, got " +
                 a.channels)
    out = os.path.abspath(a.out)
    if a.report_only:
        g = grid(a.tiny)
        rows = read_rows(os.path.join(out, "sizing_map.csv"))
        g["channels"] = [c for c in g["channels"] if any(r["channel"] == c for r in rows)]
        write(out, rows, g, a.tiny)
    else:
        run(out, a.tiny, channels, os.path.abspath(a.template_banks))
    with open(os.path.join(os.path.abspath(a.out), "sizing_map.md")) as f:
        print(f.read())


if __name__ == "__main__":
    main(sys.argv[1:])

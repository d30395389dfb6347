#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The detectability study: the smallest defect an instrument can see (Machado et al. 2014 end on
it: "due to the limited sampling frequency of measuring devices, it will not be possible to
identify defects with a small size, but the expected resolution will be better than vibrational
measurements").

The SKF 6208 at 500 rad/s under a radial load (a load zone, the outer ring centre free: the
classic bearing vibration model) is simulated healthy and with inner- and outer-race defects of
growing size (the runs go through the partition sweep in.sweep). Each run gives two channels:
the electrical one (R, measured as the voltage I·R) and the vibration one (the outer ring's
acceleration along the load, through an accelerometer). Every channel is acquired by
`ohmdem-post acquire` for each instrument (sampling rate with its anti-alias filter, noise
level, ADC bits) and diagnosed by `ohmdem-post diagnose` against the healthy run acquired by the
same instrument (--baseline).
  studies/detectability.py [--quick] [--jobs N] [--report-only] OUT
Writes into OUT:
  detectability.csv  one row per case: size_deg, defect, channel, rate_hz, bits, noise, diagnosis,
                     score, detected, identified, size_est_deg (the size diagnose states of
                     an identified race defect), note (why a case could not be analysed)
  detectability.md   the instruments, the map, and the answer to the paper's two claims
  map_*.png          smallest detected / identified size against the sampling rate
  sizing_map.*       the size estimate's error against rate and noise per channel
                     (studies/sizing_map.py; its last section of detectability.md; not
                     with --quick, whose last section points to the committed map)
"""
import argparse
import concurrent.futures as cf
import json
import math
import os
import subprocess

import common
import sizing_map
from instruments import CHANNELS, CURRENT, SENSITIVITY  # noqa: F401 (the study's chains)

BEARING = common.Bearing("machado2014")  # the deck's default bearing, from its catalog file
SHAFT_HZ = 500 / (2 * math.pi)     # the study's inner ring speed, 500 rad/s
T_FROM = 0.05          # s: after the sliding phase and the ring's settling under radial load
WINDOW = 0.5           # s analysed (40 shaft revolutions at 500 rad/s); --full: 1 s

def grid(quick):
    global WINDOW, DECK_VARS
    WINDOW = 0.5 if quick else 1.0
    DECK_VARS = {**DECK_VARS, "tend": T_FROM + WINDOW + 0.001}
    if quick:
        return {"sizes": [0.03, 0.1, 0.3, 1.0, 3.0], "rates": [1e3, 1e4, 1e5, 1e6],
                "noise": ["low", "high"], "bits": [16]}
    return {"sizes": [0.03, 0.05, 0.1, 0.2, 0.3, 0.5, 1.0, 2.0, 3.0],
            "rates": [1e3, 2e3, 5e3, 1e4, 2e4, 5e4, 1e5, 2e5, 5e5, 1e6],
            "noise": ["low", "mid", "high"], "bits": [12, 16]}


DECK_VARS = {"load": "radial", "tend": T_FROM + WINDOW + 0.001, "tslide": T_FROM}
# The radial load pushes the outer ring along -y: the balls carry it at the top, +y = 90 deg.
OUTER_POSITION = 90.0


def simulate(out, sizes):
    """The healthy run, then inner and outer defects of every size: one case table
    (doc/case_table.md: defect, size and the defect's position per row) through the partition
    sweep (2 partitions when 2 processes are there; a rerun skips the finished cases)."""
    sims = {}
    healthy = os.path.join(out, "sim", "healthy")
    if not common.finished(healthy):
        os.makedirs(healthy, exist_ok=True)
        cmd = common.deck_command(common.BEARING_DECK, [
            "-var", "out", healthy, "-log", os.path.join(healthy, "log.liggghts"),
            "-screen", "none"] + common.variables(DECK_VARS))
        common.run(cmd, os.path.join(healthy, "stdout.txt"), who="detectability")
    sims[("none", 0.0)] = healthy
    root = os.path.join(out, "sim", "defects")
    os.makedirs(root, exist_ok=True)
    table = os.path.join(out, "sim", "defect_cases.csv")
    rows = []
    for defect in ("inner", "outer"):
        # the outer pit in the middle of the load zone (+y), as in test rigs
        position = OUTER_POSITION if defect == "outer" else 0.0
        for s in sizes:
            rows.append([defect, f"{s:g}", f"{position:g}"])
            sims[(defect, s)] = os.path.join(root, f"defect_{defect}_size_{s:g}_position_{position:g}")
    common.case_table(table, ["defect", "size", "position"], rows)
    cmd = common.sweep_command(root, table, DECK_VARS, os.path.join(root, "log.sweep"), 2)
    common.run(cmd, os.path.join(root, "stdout.txt"), who="detectability", cwd=root)
    return sims


def post(args, allow_fail=False):
    return common.post(args, who="detectability", allow_fail=allow_fail)


def acquire(sim, channel, rate, noise, bits, seed, dest):
    ch = CHANNELS[channel]
    lo, hi = ch["range"]
    args = ["acquire", "--column", ch["column"], "--scale", repr(ch["scale"]),
            "--from", repr(T_FROM - 0.005), "--lowpass", repr(0.4 * rate), "--order", "4",
            "--rate", repr(rate), "--bits", str(bits), "--range", repr(lo), repr(hi),
            "--noise-density", repr(ch["noise"][noise]), "--seed", str(seed),
            "--name", "V", "--unit", "V", "--output", dest, os.path.join(sim, "signal.txt")]
    post(args)
    return dest


def instrument_tag(channel, rate, noise, bits):
    return f"{channel}_r{rate:g}_{noise}_b{bits}"


def case(out, sims, key, channel, rate, noise, bits, baselines):
    defect, size = key
    tag = instrument_tag(channel, rate, noise, bits)
    acq = os.path.join(out, "acq", f"{defect}_{size:g}_{tag}.txt")
    acquire(sims[key], channel, rate, noise, bits, 1, acq)
    r = post(["diagnose", "--format", "json", "--metadata",
              os.path.join(sims[key], "run.json"), "--from", repr(T_FROM), "--to",
              repr(T_FROM + WINDOW), "--baseline", baselines[tag], acq], allow_fail=True)
    if r.returncode != 0:  # a rate below every defect line: nothing can be said
        d = {"defect": "not_analysable", "score": 0.0, "detected": False,
             "error": r.stderr.strip().replace("ERROR: ", "").replace(",", ";")}
    else:
        d = json.loads(r.stdout)
    detected = bool(d.get("detected", d["defect"] != "none"))
    identified = detected and d["defect"] == defect
    size_est = d.get("size_deg")
    return {"size_deg": size, "defect": defect, "channel": channel, "rate_hz": rate, "bits": bits,
            "noise": noise, "noise_density": CHANNELS[channel]["noise"][noise],
            "diagnosis": d["defect"], "score": d.get("score", 0.0), "detected": detected,
            "identified": identified,
            "size_est_deg": size_est if identified and size_est is not None else "",
            "note": d.get("error", "")}


def write_map(out, rows, g):
    """Smallest size detected (and identified) against the sampling rate: one curve per
    channel and noise level (the finest ADC), for each defect kind."""
    bits = max(g["bits"])
    pngs = []
    for defect in ("inner", "outer"):
        for what in ("detected", "identified"):
            dat = os.path.join(out, f"map_{defect}_{what}.dat")
            series = []
            with open(dat, "w") as f:
                for channel in CHANNELS:
                    for noise in g["noise"]:
                        f.write(f"# {channel} {noise}\n")
                        for rate in g["rates"]:
                            ok = [r["size_deg"] for r in rows if r["defect"] == defect and
                                  r["channel"] == channel and r["noise"] == noise and
                                  r["bits"] == bits and r["rate_hz"] == rate and r[what]]
                            # not seen at any size: drawn above the largest size
                            f.write(f"{rate:g} {min(ok) if ok else 2 * max(g['sizes']):g}\n")
                        f.write("\n\n")
                        series.append(f"{channel}, {noise} noise")
            png = os.path.join(out, f"map_{defect}_{what}.png")
            plots = ", ".join(
                f"'{dat}' index {i} using 1:2 with linespoints lw 2 "
                f"dt {1 if s.startswith('R') else 2} title '{s}'" for i, s in enumerate(series))
            script = (f"set terminal pngcairo size 1000,600; set output '{png}'; set logscale xy; "
                      f"set xlabel 'sampling rate (Hz)'; set ylabel 'smallest {what} size (deg)'; "
                      f"set yrange [{min(g['sizes']) / 1.5}:{3 * max(g['sizes'])}]; "
                      f"set title '{defect}-race defect, {bits}-bit ADC: smallest {what} size "
                      f"(top = not {what} at any size)'; set key outside right; plot {plots}")
            subprocess.run(["gnuplot", "-e", script], check=True)
            pngs.append(png)
    return pngs


def write_example(out, sims, rate=1e4, noise="high", bits=16, size=1.0):
    """What an instrument sees: the simulated R and ring acceleration of the 1 deg inner defect
    against what a 10 kHz, noisy instrument records (back in ohm and m/s^2)."""
    sim = os.path.join(sims[("inner", size)], "signal.txt")
    with open(sim) as f:
        names = f.readline().lstrip("#").split()
    t0, t1 = T_FROM + 0.05, T_FROM + 0.07
    panels = []
    for channel, unit in (("R", "R (ohm)"), ("acc", "acceleration along the load (m/s^2)")):
        ch = CHANNELS[channel]
        acq = os.path.join(out, "acq", f"inner_{size:g}_{instrument_tag(channel, rate, noise, bits)}.txt")
        col = names.index(ch["column"]) + 1
        panels.append(
            f"set ylabel '{unit}'; plot '{sim}' every 4 using ($1>{t0} && $1<{t1} ? $1 : 1/0):{col} "
            f"with lines lc rgb '#999999' title 'simulated (1 MHz)', "
            f"'{acq}' using ($1>{t0} && $1<{t1} ? $1 : 1/0):($2/{ch['scale']!r}) with linespoints "
            f"pt 7 ps 0.4 lc rgb '#cc2222' title 'acquired: {rate:g} Hz, {noise} noise, {bits} bits'")
    png = os.path.join(out, "acquired_example.png")
    script = (f"set terminal pngcairo size 1000,700; set output '{png}'; set multiplot layout 2,1 "
              f"title '1 deg inner-race defect, radial load, 500 rad/s: simulated and acquired'; "
              f"set xlabel 'time (s)'; set xrange [{t0}:{t1}]; set key top right; "
              + "; ".join(panels) + "; unset multiplot")
    subprocess.run(["gnuplot", "-e", script], check=True)
    return png


def smallest(rows, **where):
    ok = [r["size_deg"] for r in rows if r["defect"] != "none" and
          all(r[k] == v for k, v in where.items())]
    return min(ok) if ok else None


def write_report(out, rows, g, quick, pngs):
    cols = ["size_deg", "defect", "channel", "rate_hz", "bits", "noise", "noise_density",
            "diagnosis", "score", "detected", "identified", "size_est_deg", "note"]
    with open(os.path.join(out, "detectability.csv"), "w") as f:
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join(("yes" if r[c] else "no") if isinstance(r[c], bool) else
                             (f"{r[c]:.6g}" if isinstance(r[c], float) else str(r[c]))
                             for c in cols) + "\n")
    bits = max(g["bits"])
    healthy = [r for r in rows if r["defect"] == "none"]
    false_alarms = sum(r["detected"] for r in healthy)
    lines = ["# Detectability study, machado2014 (the paper's model of an SKF 6208) (ohmdem)", "",
             f"Regenerated at {common.made_at()} by `studies/detectability.py {'--quick ' if quick else ''}OUT`. "
             f"500 rad/s, radial load 320 N on a free outer ring (load zone at the top), defects "
             f"from t = 0 (outer: centred in the load zone, {OUTER_POSITION:g} deg), "
             f"analysis window {T_FROM:g}-{T_FROM + WINDOW:g} s ({WINDOW:g} s, "
             f"{WINDOW * 500 / (2 * math.pi):.0f} shaft revolutions). "
             "Each record is acquired by `ohmdem-post acquire` (4th-order Butterworth anti-alias at "
             "0.4 x the rate, white noise, ADC) and diagnosed by `ohmdem-post diagnose` against the "
             "healthy run acquired by the same instrument (`--baseline`, another noise seed).", "",
             "| channel | signal to the ADC | ADC range | noise low / mid / high (V/sqrt(Hz)) |",
             "|---|---|---|---|"]
    for name, ch in CHANNELS.items():
        lines.append(f"| {name} | {ch['column']} x {ch['scale']:g} V | {ch['range'][0]:g} to "
                     f"{ch['range'][1]:g} V | " + " / ".join(f"{ch['noise'][k]:.3g}" for k in
                                                           ("low", "mid", "high")) + " |")
    lines += ["", f"Sizes {', '.join(f'{s:g}' for s in g['sizes'])} deg; rates "
              f"{', '.join(f'{r:g}' for r in g['rates'])} Hz; noise {', '.join(g['noise'])}; "
              f"ADC {', '.join(str(b) for b in g['bits'])} bits. {len(rows)} cases.", "",
              f"False alarms on the healthy run (a second noise seed against the baseline): "
              f"{false_alarms} of {len(healthy)} acquisitions.", "",
              f"## Smallest detected / identified size (deg), {bits}-bit ADC", "",
              "| defect | channel | noise | " + " | ".join(f"{r:g} Hz" for r in g["rates"]) + " |",
              "|---|---|---|" + "---|" * len(g["rates"])]
    for defect in ("inner", "outer"):
        for channel in CHANNELS:
            for noise in g["noise"]:
                cells = []
                for rate in g["rates"]:
                    d = smallest(rows, defect=defect, channel=channel, noise=noise, bits=bits,
                                 rate_hz=rate, detected=True)
                    i = smallest(rows, defect=defect, channel=channel, noise=noise, bits=bits,
                                 rate_hz=rate, identified=True)
                    cells.append(f"{'-' if d is None else f'{d:g}'} / {'-' if i is None else f'{i:g}'}")
                lines.append(f"| {defect} | {channel} | {noise} | " + " | ".join(cells) + " |")
    lines += ["", "(detected / identified; - : not at any size of the grid)", ""]
    lines += [f"![{os.path.basename(p)}]({os.path.basename(p)})" for p in pngs] + [""]
    lines += answer(rows, g)
    open(os.path.join(out, "detectability.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def size_error(rows, channel, defect, size, rate, noise, bits):
    """Relative error of the size estimate, or None when not identified or not sized."""
    for r in rows:
        if (r["channel"], r["defect"], r["size_deg"], r["rate_hz"], r["noise"], r["bits"]) == \
                (channel, defect, size, rate, noise, bits) and r["size_est_deg"] != "":
            return r["size_est_deg"] / size - 1
    return None


def lowest_rate(rows, g, channel, defect, size, noise, bits, ok):
    rates = sorted(r["rate_hz"] for r in rows if r["channel"] == channel and
                   r["defect"] == defect and r["size_deg"] == size and r["bits"] == bits and
                   r["noise"] == noise and ok(r))
    return rates[0] if rates else None


def answer(rows, g):
    """The paper's two claims, in numbers from the map."""
    bits = max(g["bits"])
    hz = lambda v: "-" if v is None else f"{v:g} Hz"
    out = ["## Lowest sampling rate that identifies each size", "",
           f"{bits}-bit ADC; '-': not at any rate of the grid.", "",
           "| channel | defect | noise | " + " | ".join(f"{s:g} deg" for s in g["sizes"]) + " |",
           "|---|---|---|" + "---|" * len(g["sizes"])]
    for channel in CHANNELS:
        for defect in ("inner", "outer"):
            for noise in g["noise"]:
                out.append(f"| {channel} | {defect} | {noise} | " + " | ".join(
                    hz(lowest_rate(rows, g, channel, defect, s, noise, bits,
                                   lambda r: r["identified"])) for s in g["sizes"]) + " |")
    out += ["", "## Size estimate against the sampling rate", "",
            "Relative error of the size `diagnose` states (lowest noise, "
            f"{bits} bits; '-': not identified, or the size not determined: under this radial "
            "load plain `diagnose` sizes only with the scene's model data).", "",
            "| channel | defect | size | " + " | ".join(f"{r:g} Hz" for r in g["rates"]) + " |",
            "|---|---|---|" + "---|" * len(g["rates"])]
    noise0 = g["noise"][0]
    for channel in CHANNELS:
        for defect in ("inner", "outer"):
            for size in g["sizes"]:
                cells = []
                for rate in g["rates"]:
                    e = size_error(rows, channel, defect, size, rate, noise0, bits)
                    cells.append("-" if e is None else f"{100 * e:+.0f} %")
                out.append(f"| {channel} | {defect} | {size:g} deg | " + " | ".join(cells) + " |")

    # the answers, computed from the rows
    within = lambda r: r["size_est_deg"] != "" and abs(r["size_est_deg"] / r["size_deg"] - 1) <= 0.25
    smallest_size = min(g["sizes"])
    id_rate = {c: lowest_rate(rows, g, c, "inner", smallest_size, noise0, bits,
                              lambda r: r["identified"]) for c in CHANNELS}
    sized = {size: lowest_rate(rows, g, "R", "inner", size, noise0, bits, within)
             for size in g["sizes"]}
    not_analysable = sorted({r["rate_hz"] for r in rows if r["diagnosis"] == "not_analysable"})
    unidentified_slow = sorted({r["rate_hz"] for r in rows if r["defect"] != "none" and
                                r["diagnosis"] == "unidentified" and r["rate_hz"] < 1300})
    acc_best = min((r["size_deg"] for r in rows if r["channel"] == "acc" and
                    r["defect"] == "inner" and r["noise"] == noise0 and r["bits"] == bits and
                    r["identified"]), default=None)
    at = lambda v: "at no rate of the grid" if v is None else f"from {v:g} Hz"
    out += ["", "## The paper's two claims", "",
            "*\"Due to the limited sampling frequency of measuring devices, it will not be possible "
            "to identify defects with a small size.\"* Identification does not need the pulse "
            "resolved, only the defect lines below the instrument's Nyquist frequency: at 500 rad/s "
            f"BPFO is {BEARING.bpfo_order() * SHAFT_HZ:.0f} Hz and BPFI "
            f"{BEARING.bpfi_order() * SHAFT_HZ:.0f} Hz"
            + (f"; at {', '.join(f'{r:g}' for r in not_analysable)} Hz no race defect can be "
               "analysed at all" if not_analysable else "")
            + (f"; at {', '.join(f'{r:g}' for r in unidentified_slow)} Hz the defects are "
               "detected but stay unidentified (the race families lie above Nyquist)"
               if unidentified_slow else "")
            + f". The smallest defect of the grid ({smallest_size:g} deg) is identified "
            f"electrically {at(id_rate['R'])}; by vibration "
            + (f"{at(id_rate['acc'])}" if id_rate["acc"] is not None else
               f"the smallest identified inner defect is {acc_best:g} deg" if acc_best else
               "no inner defect is identified")
            + " (inner race, lowest noise). What the sampling rate does limit is the *size*: the "
            "size estimate of an inner defect is within 25 % "
            + ", ".join(f"{at(sized[sz])} for {sz:g} deg" for sz in g["sizes"])
            + " (electrical channel). The claim holds for sizing, not for detection or "
            "identification. The simulation itself samples at 1 MHz (dt = 1e-6 s): a "
            f"{smallest_size:g} deg inner defect is crossed in "
            f"{smallest_size * math.pi / 180 / (500 - BEARING.cage_speed(500)) * 1e6:.1f} us, so its size is "
            "not resolved even in the simulated signal.", ""]
    comparisons = []
    for defect in ("inner", "outer"):
        for noise in g["noise"]:
            for rate in g["rates"]:
                r = smallest(rows, defect=defect, channel="R", noise=noise, bits=bits,
                             rate_hz=rate, identified=True)
                a = smallest(rows, defect=defect, channel="acc", noise=noise, bits=bits,
                             rate_hz=rate, identified=True)
                comparisons.append((defect, noise, rate, r, a))
    better = sum(1 for *_, r, a in comparisons if r is not None and (a is None or r < a))
    equal = sum(1 for *_, r, a in comparisons if r == a)
    worse = len(comparisons) - better - equal
    out += ["*\"The expected resolution will be better than vibrational measurements.\"* Over the "
            f"{len(comparisons)} instrument settings (defect x noise x rate, {bits} bits), the "
            f"electrical channel identifies a smaller defect than the accelerometer in {better}, "
            f"the same in {equal} and a larger one in {worse}. "
            "The vibration channel here is the ideal one (the ring's own acceleration, no housing, "
            "no transmission path, no other machine); the difference shows at the higher "
            "accelerometer noise levels. The size estimate is the electrical channel's clearer "
            "advantage: the contact breaks give rectangular pulses whose width is the defect's "
            "angular size, where the ring's acceleration rings at its contact resonance.", ""]
    return out


def read_rows(path):
    """The rows of a detectability.csv, typed as the study made them."""
    import csv
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            for k in ("size_deg", "rate_hz", "score", "noise_density"):
                r[k] = float(r[k])
            r["bits"] = int(r["bits"])
            r["detected"], r["identified"] = r["detected"] == "yes", r["identified"] == "yes"
            r["size_est_deg"] = float(r["size_est_deg"]) if r["size_est_deg"] else ""
            rows.append(r)
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out", help="output folder")
    p.add_argument("--quick", action="store_true", help="reduced grid (under 5 minutes)")
    p.add_argument("--jobs", type=int, default=2, help="acquisitions in parallel [2]")
    p.add_argument("--report-only", action="store_true",
                   help="rewrite the report and figures from OUT/detectability.csv")
    a = p.parse_args()
    out = os.path.abspath(a.out)
    g = grid(a.quick)
    if a.report_only:
        rows = read_rows(os.path.join(out, "detectability.csv"))
        sims = {("inner", 1.0):
                os.path.join(out, "sim", "defects", "defect_inner_size_1_position_0")}
        example = os.path.join(out, "acquired_example.png")
        if os.path.isdir(sims[("inner", 1.0)]):
            example = write_example(out, sims)
        pngs = write_map(out, rows, g) + ([example] if os.path.exists(example) else [])
        write_report(out, rows, g, a.quick, pngs)
        append_sizing_map(out, a.quick)
        return
    os.makedirs(os.path.join(out, "acq"), exist_ok=True)
    sims = simulate(out, g["sizes"])
    instruments = [(c, r, n, b) for c in CHANNELS for r in g["rates"] for n in g["noise"]
                   for b in g["bits"]]
    baselines = {}
    for c, r, n, b in instruments:  # the healthy run through the same instrument, seed 2
        tag = instrument_tag(c, r, n, b)
        baselines[tag] = os.path.join(out, "acq", f"baseline_{tag}.txt")
    with cf.ThreadPoolExecutor(a.jobs) as ex:
        list(ex.map(lambda i: acquire(sims[("none", 0.0)], *i, 2,
                                      baselines[instrument_tag(*i)]), instruments))
        jobs = [(k, *i) for k in sims for i in instruments]
        rows = list(ex.map(lambda j: case(out, sims, j[0], *j[1:], baselines), jobs))
    rows.sort(key=lambda r: (r["defect"], r["channel"], r["size_deg"], r["rate_hz"], r["noise"],
                             r["bits"]))
    pngs = write_map(out, rows, g) + [write_example(out, sims)]
    write_report(out, rows, g, a.quick, pngs)
    if not a.quick:  # the size's error against rate and noise
        sizing_map.run(out)
    append_sizing_map(out, a.quick)


def append_sizing_map(out, quick):
    """The sizing map (studies/sizing_map.py, written into OUT) as the report's last section;
    with --quick a pointer to the committed one (its own command makes it: a tiny map's
    figures beside the full map's would contradict them)."""
    if quick:
        with open(os.path.join(out, "detectability.md"), "a") as f:
            f.write("\n## Sizing map\n\nNot made by `--quick`: the size's error against rate "
                    "and noise per channel is [sizing_map.md](sizing_map.md), made by its own "
                    "command (`studies/sizing_map.py OUT`).\n")
        return
    path = os.path.join(out, "sizing_map.md")
    if not os.path.exists(path):
        return
    with open(path) as f:
        body = f.read().split("\n", 1)[1]  # without its title
    with open(os.path.join(out, "detectability.md"), "a") as f:
        f.write("\n## Sizing map\n" + body)


if __name__ == "__main__":
    main()

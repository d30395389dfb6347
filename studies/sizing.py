#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The sizing study: how well `ohmdem-post diagnose` sizes and places a race defect
from what an instrument records of the electrical channel.

The SKF 6208 of the detectability study (500 rad/s) is simulated with inner and outer defects of
0.3 to 3 deg under the radial load (pit at the load zone's centre; inner pits at several places
on the ring) and under the fixed (balanced) load. The pits are 50 um deep: the ball reaches the
floor only in the 3 deg outer pit (1.92 mm > 2 sqrt(Db depth) = 1.59 mm); see doc/methods/size_pulse_area.md,
"Size and position". Each run is acquired at 10, 20 and 50 kHz, 16 bits,
with the detectability study's low and high electrical noise, given a shaft-angle column (the
deck's angle_inner, 500 rad/s x t) and diagnosed four ways: 'jump' (area / (jump x level); the
radial load's jump from one calibration run that is not among the cases, an outer pit of 0.7 deg
at 1 MHz; the fixed load's the theory 1/(Nb-1)) and 'curve' (diagnose --size-curve: the model's
curve from 1 MHz runs of the scene at sizes none of the cases has; 'chain curve': the same runs
through the record's instrument, the interval with the curve's own error measured on runs at
still other sizes, --size-model-error; the 1 MHz curve's own error too) and 'width or chain
curve' (also --width-curve: the pulses' entry-to-exit width through the instrument, used where
it resolves the crossing). The force load is simulated at the radial load's sizes.
  studies/sizing.py [--quick] OUT
Writes OUT/sizing.csv (one row per case, instrument and method), OUT/sizing.md (the tables)
and OUT/curve_<defect>_<load>[_r<rate>_<noise>].txt, OUT/width_<defect>_<load>_r<rate>_<noise>.txt
(the model's curves).
"""
import argparse
import json
import math
import os
import sys

import common
import instruments

OMEGA = 500.0
T_FROM, WINDOW = 0.05, 0.3
DEPTH = 5e-5
RATES = [1e4, 2e4, 5e4]
NOISE = ["low", "high"]
CALIBRATION = ("outer", 0.7, "radial", 90.0)
# the model's curve: the same scene at sizes none of the cases has, 0.15 s at 1 MHz each, at
# most ~30 % apart above 0.7 deg (linear interpolation between them: the first curve, 0.2, 0.4,
# 0.7, 1.5, 2.5, 4 deg, read 1 deg pits 3-8 % high, more than its error runs showed)
CURVE_SIZES = [0.2, 0.4, 0.7, 0.85, 1.1, 1.5, 1.8, 2.5, 3.2, 4.0]
# the curve's own error: runs of the same scene at sizes neither the curve nor the cases have,
# through the same chain; the RMS of their area over the curve's, relative (diagnose
# --size-model-error), combined in the interval with the pass-to-pass scatter
ERROR_SIZES = [0.25, 0.6, 1.2, 2.2, 3.5]
T975 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571}  # Student's t, P(T > t) = 0.025

# The accelerometer: 10 mV/g (1.02e-3 V per m/s^2) on a +-5 V input, so that the simulated
# impacts (up to ~3000 m/s^2 at 1 MHz) are not clipped; the noise densities are the
# detectability study's in m/s^2/sqrt(Hz) (5e-5 and 5e-3: a good piezoelectric sensor, a MEMS).
ACC_SENSITIVITY = 1.02e-3
ACC_NOISE = {"low": 5e-5, "mid": 5e-4, "high": 5e-3}


def cases(quick):
    c = []
    sizes = [0.3, 1.0, 3.0] if quick else [0.3, 0.5, 1.0, 2.0, 3.0]
    for defect in ("inner", "outer"):
        for s in sizes:
            c.append((defect, s, "radial", 90.0))
        for s in ([1.0] if quick else [0.3, 1.0, 3.0]):
            c.append((defect, s, "fixed", 90.0))
    c += [("inner", 1.0, "radial", 200.0), ("inner", 0.5, "radial", 330.0)]
    # outer pits 30 and 60 deg from the load direction (+y, 90 deg): sized on the curve of a pit
    # at the zone's centre, the place not being known
    c += [("outer", s, "radial", p) for s in (1.0, 2.0) for p in (120.0, 150.0)]
    # the force load (the ring free to tighten): every ball loaded alike as under the fixed
    # load, but on the fixed load's curves its 1 deg pits read -53 % (inner) and +11 % (outer):
    # the free ring moves while a ball is off, so it has its own curves; 0.3-3 deg as radial
    c += [(d, s, "force", 90.0) for d in ("inner", "outer") for s in sizes]
    return c


def simulate(out, case, tend, extra=None):
    """The case's run to tend s (cached under out/sim); extra: more deck variables {name:
    value} (named in the folder)."""
    defect, size, load, position = case
    extra = extra or {}
    d = os.path.join(out, "sim", f"{defect}_{size:g}_{load}_p{position:g}"
                     + "".join(f"_{k}{v}" for k, v in sorted(extra.items())))
    if not common.finished(d):
        os.makedirs(d, exist_ok=True)
        cmd = common.deck_command(common.BEARING_DECK, [
            "-var", "out", d, "-log", os.path.join(d, "log.liggghts"), "-screen", "none"] +
            common.variables({"defect": defect, "size": size, "load": load, "position": position,
                              "depth": DEPTH, "tend": tend, "tslide": T_FROM, **extra}))
        common.run(cmd, os.path.join(d, "stdout.txt"), who="sizing")
    return d


def calibrate(out):
    """The relative jump of R while the ball in the pit is off: the pulses' plateau over the
    level before them, median over the passes (1 MHz)."""
    import numpy as np
    s = common.read_signal(os.path.join(simulate(out, CALIBRATION, T_FROM + 0.1), "signal.txt"),
                           T_FROM)
    r = s["R"]
    level = np.median(r)
    above = r > level * 1.05
    starts = np.flatnonzero(np.diff(above.astype(int)) == 1)
    jumps = [(r[i:i + 8].max() - np.median(r[max(i - 60, 0):i - 5])) / np.median(r[max(i - 60, 0):i - 5])
             for i in starts if i > 60]
    return float(np.median(jumps))


_STATS = {}


def window_area(out, defect, size, load, rate=None, noise=None, tend=T_FROM + 0.15):
    """The fixed-window pulse area over the level of a run of the scene (pit at the load zone's
    centre), at 1 MHz or through the instrument's chain (rate, noise); None if not measured."""
    return window_stats(out, defect, size, load, rate, noise, tend).get("pulse_window_rel_area_s")


def edge_width(out, defect, size, load, rate, noise):
    """The pulses' entry-to-exit width (s) of a run of the scene through the chain; None if not
    measured."""
    return window_stats(out, defect, size, load, rate, noise).get("pulse_edge_width_s")


def window_stats(out, defect, size, load, rate=None, noise=None, tend=T_FROM + 0.15):
    """diagnose's JSON on a run of the scene (pit at the load zone's centre), at 1 MHz or
    through the instrument's chain; {} when the chain cannot record it."""
    key = (out, defect, size, load, rate, noise, tend)
    if key not in _STATS:
        _STATS[key] = _window_stats(out, defect, size, load, rate, noise, tend)
    return _STATS[key]


def _window_stats(out, defect, size, load, rate, noise, tend):
    sim = simulate(out, (defect, size, load, 90.0), tend)
    record, column = os.path.join(sim, "signal.txt"), "R"
    if rate:
        record, column = os.path.join(out, "acq", f"curve_{defect}_{size:g}_{load}_r{rate:g}_"
                                      f"{noise}.txt"), "V"
        if not acquire_with_angle(sim, load, rate, noise, record, allow_fail=True):
            return {}  # e.g. R infinite (no ball touching: the force load's 4 deg outer pit)
    r = common.post(["diagnose", "--format", "json", "--column", column, "--metadata",
                     os.path.join(sim, "run.json"), "--from", repr(T_FROM), "--assume-defect",
                     defect, "--pulse-height", "1", record], who="sizing")
    return json.loads(r.stdout)


def curve_error(out, defect, load, rows, rate, noise, measure=None, keep=None):
    """The curve's relative error: RMS over the ERROR_SIZES runs within the curve (and kept by
    keep(size)) of their area (or measure(out, defect, size, load, rate, noise)) over the
    curve's (linear interpolation) minus one, times t(0.975, n runs) / 1.96; None when none is
    within it."""
    dev = []
    for size in ERROR_SIZES:
        if not rows[0][0] <= size <= rows[-1][0] or (keep and not keep(size)):
            continue
        a = (measure or window_area)(out, defect, size, load, rate, noise)
        k = next(i for i in range(1, len(rows)) if size <= rows[i][0])
        (s0, a0), (s1, a1) = rows[k - 1], rows[k]
        if a is not None:
            dev.append(a / (a0 + (a1 - a0) * (size - s0) / (s1 - s0)) - 1)
    if not dev:
        return None
    # a spread measured on n runs: Student's t with n degrees of freedom, written as the
    # normal deviate's multiple diagnose applies (1.96 at 95 %)
    return (sum(d * d for d in dev) / len(dev)) ** 0.5 * T975[min(len(dev), 5)] / 1.96


def model_curve(out, defect, load, rate=None, noise=None):
    """The fixed-window pulse area over the level against the size, from simulations of the
    scene (pit at the load zone's centre) at 1 MHz, or passed through the instrument's chain
    (rate, noise); cut where the area stops increasing."""
    rows = []
    for size in CURVE_SIZES:
        a = window_area(out, defect, size, load, rate, noise)
        if a is None or (rows and a <= rows[-1][1]):
            break
        rows.append((size, a))
    err = curve_error(out, defect, load, rows, rate, noise)
    tag = f"_r{rate:g}_{noise}" if rate else ""
    path = os.path.join(out, f"curve_{defect}_{load}{tag}.txt")
    write_curve(path, f"{defect} defect, {load} load{', ' + tag[1:] if tag else ', 1 MHz'}: "
                "size_deg, fixed-window pulse area / level (s)",
                f"the area at {sizes_text(ERROR_SIZES)} deg, x t(0.975, runs) / 1.96", err,
                "--size-model-error", rows)
    return path, rows, err


def sizes_text(sizes):
    return ', '.join(f'{x:g}' for x in sizes)


def write_curve(path, title, error_of, err, flag, rows):
    """A model curve diagnose reads: its title, its own error (relative RMS of `error_of`) with
    the diagnose flag that takes it, then `SIZE VALUE` lines."""
    with open(path, "w") as f:
        f.write(f"# {title}\n")
        if err is not None:
            f.write(f"# model error (relative RMS of {error_of}): {err:.4f}; diagnose {flag} "
                    f"{err:.4f}\n")
        for size, value in rows:
            f.write(f"{size:g} {value!r}\n")


def crossing_s(defect, size):
    """How long a ball stays in a pit of `size` deg at the study's speed (s)."""
    b = common.Bearing()
    order = b.bpfi_order() if defect == "inner" else b.bpfo_order()
    return size * math.pi / 180 * b.nb / (2 * math.pi * order * OMEGA / (2 * math.pi))


def width_curve(out, defect, load, rate, noise):
    """The pulses' entry-to-exit width against the size through the instrument's chain: the
    longest run of CURVE_SIZES over which it increases; its own error from the ERROR_SIZES runs
    whose crossing lasts 2 samples or more (where diagnose uses the width). (path, rows, err);
    path None when fewer than two points increase."""
    pts = [(s, edge_width(out, defect, s, load, rate, noise)) for s in CURVE_SIZES]
    best, run = [], []
    for s, w in pts:
        if w is not None and (not run or w > run[-1][1]):
            run.append((s, w))
        else:
            run = [(s, w)] if w is not None else []
        if len(run) > len(best):
            best = list(run)
    if len(best) < 2:
        return None, best, None
    err = curve_error(out, defect, load, best, rate, noise, edge_width,
                      lambda s: crossing_s(defect, s) * rate >= 2)
    path = os.path.join(out, f"width_{defect}_{load}_r{rate:g}_{noise}.txt")
    write_curve(path, f"{defect} defect, {load} load, r{rate:g}_{noise}: size_deg, entry-to-exit "
                "width (s)", f"the width at the resolved ones of {sizes_text(ERROR_SIZES)} deg, "
                "x t(0.975, runs) / 1.96", err, "--width-model-error", best)
    return path, best, err


def with_angle(record, dest):
    """An acquired record (time, V) into dest with the deck's shaft angle omega t as a third
    column, angle_inner; the record removed. Written whole, then renamed: a run stopped halfway
    leaves no short record in a cache."""
    part = dest + ".part"
    with open(record) as f, open(part, "w") as g:
        for line in f:
            if line.startswith("#"):
                g.write(line if not line.startswith("# time") else "# time V angle_inner\n")
            else:
                t, v = line.split()
                g.write(f"{t} {v} {OMEGA * float(t)!r}\n")
    os.replace(part, dest)
    os.remove(record)


def acquire_acc(sim, rate, noise, dest, across=False):
    """The ring's acceleration along the load through the accelerometer's chain (column V);
    across: the sensor's second axis too (acc_across as V2, its own noise: acquire's seed + 1)."""
    second = ["--across-column", "acc_across", "--across-name", "V2"] if across else []
    common.post(["acquire", "--column", "acc_along", *second, "--scale", repr(ACC_SENSITIVITY),
                 "--from", repr(T_FROM), "--lowpass", repr(0.4 * rate), "--order", "4",
                 "--rate", repr(rate), "--bits", "16", "--range", "-5", "5",
                 "--noise-density", repr(ACC_NOISE[noise] * ACC_SENSITIVITY), "--seed", "1",
                 "--name", "V", "--unit", "V", "--output", dest,
                 os.path.join(sim, "signal.txt")], who="sizing")
    return dest


def acquire_with_angle(sim, load, rate, noise, dest, allow_fail=False, seed=1):
    """The electrical channel acquired, plus the shaft angle the deck's angle_inner holds. The
    fixed load's level (1.38 ohm x 0.1 A) needs a 0-0.2 V range. seed: the acquisition noise's
    (the study's and the banks' 1; studies/template_heldout.py another)."""
    ch = instruments.CHANNELS["R"]
    lo, hi = ch["range"] if load == "radial" else (0.0, 0.2)
    tmp = dest + ".acq"
    r = common.post(["acquire", "--column", "R", "--scale", repr(ch["scale"]), "--from",
                     repr(T_FROM), "--lowpass", repr(0.4 * rate), "--order", "4", "--rate",
                     repr(rate), "--bits", "16", "--range", repr(lo), repr(hi),
                     "--noise-density", repr(ch["noise"][noise]), "--seed", str(seed),
                     "--name", "V", "--unit", "V", "--output", tmp, os.path.join(sim, "signal.txt")],
                    who="sizing", allow_fail=allow_fail)
    if r.returncode != 0:
        return False
    with_angle(tmp, dest)
    return True


def diagnose(sim, acq, defect, load, height, curve=None, error=None, width=None):
    """The size and place of the run's defect (--assume-defect: the study measures the sizing;
    the identification is in the CSV). width: (width curve, its error) or None."""
    args = ["diagnose", "--format", "json", "--column", "V", "--metadata",
            os.path.join(sim, "run.json"), "--from", repr(T_FROM), "--assume-defect", defect, acq]
    if curve:
        args += ["--size-curve", curve]
        if error:
            args += ["--size-model-error", repr(error)]
    if width and width[0]:
        args += ["--width-curve", width[0]]
        if width[1]:
            args += ["--width-model-error", repr(width[1])]
    elif load == "radial":
        args += ["--pulse-height", repr(height)]
    r = common.post(args, who="sizing", allow_fail=True)
    return json.loads(r.stdout) if r.returncode == 0 else {"defect": "error"}


def row(d, case, rate, noise, method):
    """One CSV row: the estimate against the size and place the deck was given."""
    defect, size, load, position = case
    est = d.get("size_deg") if d.get("size_interval_deg") else None
    iv = d.get("size_interval_deg") or [None, None]
    covers = est is not None and iv[0] is not None and iv[0] <= size and \
        (iv[1] is None or size <= iv[1])
    pos = d.get("position_deg") if est is not None else None
    perr = None if pos is None else (pos - position + 180) % 360 - 180
    mod = d.get("position_modulo_deg")
    if pos is not None and mod:  # an outer pit: from the load zone's centre (90 deg), modulo
        perr = (pos - (position - 90) + mod / 2) % mod - mod / 2
    return {"defect": defect, "size_deg": size, "load": load, "position_deg": position,
            "rate_hz": rate, "noise": noise, "method": method, "diagnosis": d["defect"],
            "size_deg_est": est, "low": iv[0], "high": iv[1],
            "error_pct": None if est is None else 100 * (est / size - 1), "covers": covers,
            "position_est_deg": pos, "position_error_deg": perr,
            "size_from": "width" if str(d.get("size_method", "")).startswith("pulse edges")
            else "area"}


def summary(rows):
    """Per (load, defect kind, rate, noise): cases sized, median and largest |error| (%),
    coverage of the interval (of all the cases: one not sized is not covered), largest inner
    position error (deg)."""
    out = {}
    for r in rows:
        kind = r["defect"] + (" off the zone's centre" if r["defect"] == "outer" and
                              r["load"] == "radial" and r["position_deg"] != 90 else "")
        out.setdefault((r["method"], r["load"], kind, r["rate_hz"], r["noise"]), []).append(r)
    lines = ["| size from | load | defect | rate (Hz) | noise | sized | median abs error | "
             "largest abs error | interval covers | largest position error (deg) | by width |",
             "|---" * 11 + "|"]
    for (method, load, defect, rate, noise), rs in sorted(out.items()):
        sized = [r for r in rs if r["size_deg_est"] is not None]
        errs = sorted(abs(r["error_pct"]) for r in sized)
        cover = [r["covers"] for r in rs]
        pos = [abs(r["position_error_deg"]) for r in sized if r["position_error_deg"] is not None]
        med = f"{errs[len(errs) // 2]:.1f} %" if errs else "-"
        big = f"{errs[-1]:.1f} %" if errs else "-"
        cov = f"{sum(cover)}/{len(cover)}"
        p = f"{max(pos):.1f}" if pos else "-"
        lines.append(f"| {method} | {load} | {defect} | {rate:g} | {noise} | {len(sized)}/{len(rs)} | {med} | "
                     f"{big} | {cov} | {p} | {sum(r['size_from'] == 'width' for r in sized)} |")
    return lines


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="fewer sizes")
    ap.add_argument("out")
    a = ap.parse_args(argv)
    os.makedirs(os.path.join(a.out, "acq"), exist_ok=True)
    height = calibrate(a.out)
    curves = {(d, l): model_curve(a.out, d, l) for d in ("inner", "outer")
              for l in ("radial", "fixed", "force")}
    chain_curves, width_curves = {}, {}
    rows = []
    for case in cases(a.quick):
        defect, size, load, position = case
        sim = simulate(a.out, case, T_FROM + WINDOW)
        for rate in RATES:
            for noise in NOISE:
                acq = os.path.join(a.out, "acq", f"{defect}_{size:g}_{load}_p{position:g}_"
                                   f"r{rate:g}_{noise}.txt")
                acquire_with_angle(sim, load, rate, noise, acq)
                key = (defect, load, rate, noise)
                if key not in chain_curves:
                    chain_curves[key] = model_curve(a.out, defect, load, rate, noise)
                    width_curves[key] = width_curve(a.out, defect, load, rate, noise)
                for method in ("jump", "curve", "chain curve", "width or chain curve"):
                    curve, error, width = None, None, None
                    if method == "curve":
                        curve, error = curves[(defect, load)][0], curves[(defect, load)][2]
                    elif method != "jump":
                        curve, error = chain_curves[key][0], chain_curves[key][2]
                    if method == "width or chain curve":
                        width = (width_curves[key][0], width_curves[key][2])
                    d = diagnose(sim, acq, defect, load, height, curve, error, width)
                    rows.append(row(d, case, rate, noise, method))
    common.write_csv(os.path.join(a.out, "sizing.csv"), rows)
    lines = ["# Sizing study", "", f"Regenerated at {common.made_at()} by `studies/sizing.py {'--quick ' if a.quick else ''}"
             f"OUT`. Pits {DEPTH * 1e6:g} um deep; radial-load pulse height {height:.4f} (calibration "
             f"run: {CALIBRATION[0]} {CALIBRATION[1]} deg, 1 MHz); fixed load: 1/(Nb-1). "
             "'jump': area / (jump x level); 'curve': the fixed-window area on the model's curve "
             "('chain curve': the same runs acquired by the record's instrument) "
             "(1 MHz runs of the scene at " + ", ".join(f"{x:g}" for x in CURVE_SIZES) +
             " deg; the curves below, cut where the area stops increasing).", ""]
    for (d, l), (path, pts, _) in sorted(curves.items()):
        lines.append(f"- curve {d} {l}: " + ", ".join(f"{sz:g} deg -> {ar * 1e6:.2f} us"
                                                       for sz, ar in pts))
    lines.append("")
    lines.append("The chain curves' own error (relative RMS of the area of runs at " +
                 ", ".join(f"{x:g}" for x in ERROR_SIZES) + " deg, within the curve), in the "
                 "'chain curve' interval: " + "; ".join(
                     f"{d} {l} {r:g} Hz {n}: " + ("-" if c[2] is None else f"{c[2]:.3f}")
                     for (d, l, r, n), c in sorted(chain_curves.items())))
    lines.append("")
    lines.append("The 1 MHz curves' own error (the same runs at 1 MHz), in the 'curve' interval: " +
                 "; ".join(f"{d} {l}: " + ("-" if c[2] is None else f"{c[2]:.3f}")
                           for (d, l), c in sorted(curves.items())))
    lines.append("")
    lines.append("The width curves (entry-to-exit width through the chain, the longest increasing "
                 "run; diagnose uses the width where the crossing it gives lasts 2 samples or "
                 "more): " + "; ".join(
                     f"{d} {l} {r:g} Hz {n}: " + (", ".join(f"{s:g} deg -> {w * 1e6:.0f} us"
                                                            for s, w in c[1]) or "-") +
                     ("" if c[2] is None else f" (error {c[2]:.3f})")
                     for (d, l, r, n), c in sorted(width_curves.items())))
    lines.append("")
    lines += summary(rows)
    with open(os.path.join(a.out, "sizing.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1:])

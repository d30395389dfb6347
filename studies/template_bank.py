#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The template-fit size (`diagnose --size-method template --template-bank FILE`): a bank
of folded pulses from short simulations of the sizing study's scene at known sizes (and, for an
outer pit under the radial load, angles from the load direction), each acquired through the
record's own chain, then the study's cases (studies/sizing.py; sizes no bank run has) sized by
fitting the bank to their fold, at 10, 20, 50 kHz, low and high noise.

  studies/template_bank.py [--rates 1e4,2e4,5e4] [--noise low,high] [--kinds inner:force,...] OUT

The bank's sizes: 28 from 0.2 to 4.27 deg, 12 % apart (the radial outer pit: 14, 25 % apart, at
25 angles 2.5 deg apart); its own error (the relative RMS of the fitted size of held-out runs at
0.25, 0.6, 1.2, 2.2, 3.5 deg, x t(0.975, runs) / 1.96) is written in its header and widens the
interval. The radial outer bank's runs lie at 0 deg and halfway between its angles across the
zone (6.25, 18.75, 31.25, 43.75, 56.25 deg), and the RMS error of their fitted angle from the
load (the same factor) is its '# angle error (deg)', which widens the fit's angle interval
before a branch of the phase is picked (no line where no run gave an angle: no branch). Writes
OUT/bank_<defect>_<load>_r<rate>_<noise>.txt, OUT/template.csv (one row per case and instrument,
the columns of sizing.csv, written as it goes) and OUT/template.md.
"""
import argparse
import json
import os
import sys

import common
import fold_compare
import sizing

# the bank's sizes: 12 % apart from 0.2 deg (the fit reads between them on the parabola of the
# misfits; on the sizing study's ~30 % steps held-out `force` inner pits of 1.2 and 2.2 deg read
# +25 and -18 %). Fewer for the radial outer pit (25 % apart), which has 25 angles too. Neither
# holds a case's or an error run's size.
BANK_SIZES = [round(0.2 * 1.12 ** k, 3) for k in range(28)]
BANK_SIZES_ANGLES = [round(0.22 * 1.25 ** k, 3) for k in range(14)]
ERROR_SIZES = sizing.ERROR_SIZES
# The outer pit under the radial load: deg from the load, 2.5 apart. The fold's shape does not
# follow the angle smoothly between angles 15 or 7.5 deg apart (it changes with where the other
# balls are as one crosses the pit, which repeats every 27.7 deg): on a 15 deg grid held-out
# pits 11-41 deg off fitted angles up to 24 deg wrong, and on a 7.5 deg grid as well.
ANGLES = [2.5 * k for k in range(25)]
# held-out runs at the load line and halfway between two of the bank's angles across the zone:
# the size's error and the fitted angle's
ERROR_ANGLES = [0.0, 6.25, 18.75, 31.25, 43.75, 56.25]
TEND = sizing.T_FROM + 0.3  # as the cases: ~130 passes, ~30 samples per fine bin
KINDS = [(d, l) for l in ("force", "radial", "fixed") for d in ("inner", "outer")]


def angles_of(defect, load):
    return ANGLES if (defect, load) == ("outer", "radial") else [0.0]


def sizes_of(defect, load):
    return BANK_SIZES_ANGLES if len(angles_of(defect, load)) > 1 else BANK_SIZES


def acquired(out, defect, size, load, angle, rate, noise, seed=1, tend=TEND, allow_fail=True,
             extra=None):
    """A run of the scene to `tend` s (pit `angle` deg from the load direction; extra: more deck
    variables) acquired by the chain with the noise's `seed`: (run folder, record), cached under
    out; (None, None) when the chain cannot record it (R infinite; allow_fail False: an error)."""
    place = round(90.0 + angle, 3)
    sim = sizing.simulate(out, (defect, size, load, place), tend, extra)
    os.makedirs(os.path.join(out, "acq"), exist_ok=True)
    dest = os.path.join(out, "acq", os.path.basename(sim) + f"_r{rate:g}_{noise}"
                        + ("" if seed == 1 else f"_s{seed}") + ".txt")
    if not os.path.exists(dest) and not sizing.acquire_with_angle(
            sim, load, rate, noise, dest, allow_fail=allow_fail, seed=seed):
        return None, None
    return sim, dest


# A run whose period is a near whole number of samples leaves fold bins no pass fell in (the
# 6208's BPFI under the fixed load at 10 kHz: 16.003 samples, the passes of 0.3 s covering half
# a sample): diagnose leaves such a template out, so the run is made longer until its passes
# cover every sub-sample phase. The lengths after the sliding phase (s).
LONGER = (0.6, 1.2)


def fold(out, defect, size, load, angle, rate, noise):
    """diagnose --pulse-fold-out on the run: (lowpass line, bin s, [y], [se]) or None; a run
    whose fold has bins no pass fell in is made again LONGER."""
    for length in (None,) + LONGER:
        tend = TEND if length is None else sizing.T_FROM + length
        extra = None if length is None else {"tend": tend}  # its own folder
        sim, acq = acquired(out, defect, size, load, angle, rate, noise, tend=tend, extra=extra)
        if acq is None:
            return None
        path = acq[:-4] + ".fold"
        if not os.path.exists(path):
            r = common.post(["diagnose", "--no-size", "--format", "json", "--column", "V",
                             "--metadata", os.path.join(sim, "run.json"), "--from",
                             repr(sizing.T_FROM), "--assume-defect", defect, "--pulse-fold-out",
                             path, acq], who="template_bank", allow_fail=True)
            if r.returncode != 0:  # no fold (under half the phases covered): longer too
                continue
        head = fold_compare.read_header(path)
        if int(head.get("bins no pass fell in", "0")) == 0:
            return (head.get("lowpass", ""), head["bin (s)"]) + fold_compare.read_fold(path,
                                                                                    text=True)
    return None


def write_bank(path, defect, load, rate, noise, rows, error, angle_error=None):
    lowpass, bin_s = rows[0][2][0], rows[0][2][1]
    with open(path, "w") as f:
        sizes = sizing.sizes_text(sorted({r[0] for r in rows}))
        f.write(f"# ohmdem-post pulse template bank (studies/template_bank.py): {defect} defect, "
                f"{load} load, r{rate:g}_{noise}, sizes {sizes} deg\n")
        f.write("# bearing: machado2014\n")
        f.write(f"# defect: {defect}\n# load: {load}\n# sampling rate (Hz): {rate:g}\n")
        f.write(f"# lowpass: {lowpass}\n# bin (s): {bin_s}\n")
        f.write(f"# model error: {error:.4f}\n")
        if angle_error is not None:
            f.write(f"# angle error (deg): {angle_error:.3f}\n")
        f.write("# SIZE_DEG ANGLE_DEG N Y_1..Y_N SE_1..SE_N\n")
        for size, angle, (_, _, y, se) in rows:
            f.write(f"{size:g} {angle:g} {len(y)} {' '.join(y)} {' '.join(se)}\n")


def diagnose(out, sim, acq, defect, bank):
    r = common.post(["diagnose", "--format", "json", "--column", "V", "--metadata",
                     os.path.join(sim, "run.json"), "--from", repr(sizing.T_FROM),
                     "--assume-defect", defect, "--size-method", "template", "--template-bank",
                     bank, acq], who="template_bank", allow_fail=True)
    if r.returncode != 0:
        print(r.stderr, file=sys.stderr)
        return {"defect": "error"}
    return json.loads(r.stdout)


def make_bank(out, defect, load, rate, noise):
    """The bank and its own error: (path, error)."""
    rows = []
    for angle in angles_of(defect, load):
        for size in sizes_of(defect, load):
            fo = fold(out, defect, size, load, angle, rate, noise)
            # a size the chain cannot record (R infinite), or whose period is so near a whole
            # number of samples that even the longest run misses sub-sample phases: the bank
            # goes without it
            if fo is None:
                continue
            rows.append((size, angle, fo))
    # a full grid: the sizes every angle has
    common_sizes = set.intersection(*[{r[0] for r in rows if r[1] == a}
                                      for a in angles_of(defect, load)])
    rows = [r for r in rows if r[0] in common_sizes]
    path = os.path.join(out, f"bank_{defect}_{load}_r{rate:g}_{noise}.txt")
    write_bank(path, defect, load, rate, noise, rows, 0.0)
    dev, adev = [], []
    several = len(angles_of(defect, load)) > 1
    angles = ERROR_ANGLES if several else [0.0]
    for angle in angles:
        for size in ERROR_SIZES:
            if not min(common_sizes) <= size <= max(common_sizes):
                continue
            sim, acq = acquired(out, defect, size, load, angle, rate, noise)
            if acq is None:
                continue
            d = diagnose(out, sim, acq, defect, path)
            if d.get("size_deg") is not None and d.get("size_interval_deg"):
                dev.append(d["size_deg"] / size - 1)
            if d.get("template_angle_deg") is not None:
                adev.append(d["template_angle_deg"] - abs(angle))  # the fit's is |angle|

    def rms(x):  # times t(0.975) / 1.96 for the few runs (capped at 5)
        return (sum(v * v for v in x) / len(x)) ** 0.5 * sizing.T975[min(len(x), 5)] / 1.96 \
            if x else 0.0
    err = rms(dev)
    # the bank's angle error (a bank with several angles); no line where no run gave an angle,
    # and diagnose then picks no branch
    angle_err = rms(adev) if several and adev else None
    write_bank(path, defect, load, rate, noise, rows, err, angle_err)
    return path, err, angle_err


def write_csv(out, rows):
    common.write_csv(os.path.join(out, "template.csv"), rows)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rates", default="1e4,2e4,5e4")
    ap.add_argument("--noise", default="low,high")
    ap.add_argument("--kinds", default=",".join(f"{d}:{l}" for d, l in KINDS),
                    help="defect:load pairs")
    ap.add_argument("out")
    a = ap.parse_args(argv)
    os.makedirs(os.path.join(a.out, "acq"), exist_ok=True)
    kinds = [tuple(k.split(":")) for k in a.kinds.split(",")]
    rates = [float(r) for r in a.rates.split(",")]
    noises = a.noise.split(",")
    rows, errors = [], {}
    for rate in rates:  # one chain at a time: its banks, then its cases
        for noise in noises:
            for case in sizing.cases(False):
                defect, size, load, position = case
                if (defect, load) not in kinds:
                    continue
                sim = sizing.simulate(a.out, case, TEND)
                key = (defect, load, rate, noise)
                if key not in errors:
                    errors[key] = make_bank(a.out, defect, load, rate, noise)
                acq = os.path.join(a.out, "acq", f"case_{defect}_{size:g}_{load}_p{position:g}_"
                                   f"r{rate:g}_{noise}.txt")
                if not os.path.exists(acq):
                    sizing.acquire_with_angle(sim, load, rate, noise, acq)
                d = diagnose(a.out, sim, acq, defect, errors[key][0])
                r = sizing.row(d, case, rate, noise, "template")
                if d.get("position_reference") == "load direction" and r["position_est_deg"] \
                        is not None and not d.get("position_modulo_deg"):
                    # the branch resolved by the fit's angle: the error on the true angle
                    r["position_error_deg"] = (r["position_est_deg"] - (position - 90) + 180) \
                        % 360 - 180
                r["branch"] = d.get("position_reference") == "load direction" and \
                    not d.get("position_modulo_deg")
                print(f"{defect} {size:g} {load} p{position:g} {rate:g} {noise}: "
                      f"{r['size_deg_est']} [{r['low']}, {r['high']}] covers {r['covers']} "
                      f"pos {r['position_est_deg']} err {r['position_error_deg']} branch "
                      f"{r['branch']}", flush=True)
                rows.append(r)
                write_csv(a.out, rows)  # as it goes: a long run stopped keeps its rows
    write_csv(a.out, rows)
    lines = ["# Template-fit sizing", "", f"Regenerated at {common.made_at()} by `studies/template_bank.py OUT`. Banks: "
             f"sizes {sizing.sizes_text(BANK_SIZES)} deg (outer radial: "
             f"{sizing.sizes_text(BANK_SIZES_ANGLES)} deg at {sizing.sizes_text(ANGLES)} deg "
             "from the load), 0.3 s runs; own error from "
             f"{sizing.sizes_text(ERROR_SIZES)} deg: " + "; ".join(
                 f"{d} {l} {r:g} Hz {n}: {e[1]:.3f}" +
                 (f" (angle {e[2]:.1f} deg)" if e[2] is not None else "")
                 for (d, l, r, n), e in sorted(errors.items())),
             "", "| load | defect | size (deg) | place (deg) | rate (Hz) | noise | estimate | "
             "interval | error | covers |", "|---" * 10 + "|"]
    for r in rows:
        est = "-" if r["size_deg_est"] is None else f"{r['size_deg_est']:.3g}"
        iv = common.interval_text(r["low"], r["high"])
        err = "-" if r["error_pct"] is None else f"{r['error_pct']:+.1f} %"
        lines.append(f"| {r['load']} | {r['defect']} | {r['size_deg']:g} | {r['position_deg']:g} | "
                     f"{r['rate_hz']:g} | {r['noise']} | {est} | {iv} | {err} | "
                     f"{'yes' if r['covers'] else 'no'} |")
    lines += [""] + sizing.summary(rows)
    with open(os.path.join(a.out, "template.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1:])

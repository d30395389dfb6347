#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Is the branch of an outer pit's angle identifiable? Under the radial load the
template fit (`diagnose --size-method template`) knows an outer pit's angle from the load
direction only modulo the ball spacing (360/Nb = 27.7 deg on the 6208): a pit at theta and one at
theta - 27.7 deg (nearer the load line, of another size) see the other balls in the same places
as one crosses the pit, and may fold alike. This study simulates both and compares their folds
as the fit does.

For each case (theta, size): the record at theta (a run as studies/template_bank.py's, acquired
through the study's chain, 20 kHz, 16 bits, low noise, acquisition seed 7) and runs one ball
spacing nearer the load line at sizes 8 % apart around the size the committed bank fits best
there, until the least misfit lies between two of them (seed 8); each folded by `diagnose
--pulse-fold-out`, less the load zone's first two harmonics (as the fit), aligned (the best
shift within two samples, sub-bin) and a constant removed; chi2 over the fit's bins in units of
both folds' standard errors (the averaged pulse's), its least over the other place's sizes (the
parabola in log size). Baselines: the same run acquired with another noise seed (the
instrument's noise alone: the fold's standard error is mostly the passes' own scatter, which a
second acquisition repeats), the same scene's next 0.3 s (an independent realization of that
scatter: chi2 ~ the number of bins when the standard errors hold), and the same place at the
size 4 % larger. d' = sqrt(chi2 other - chi2 next 0.3 s) is the difference beyond the averaged
pulse's scatter in standard errors: several, the branches part in principle; about 1 or less,
they do not. Also the chi2 with the fit's allowance for two runs' differences (2 % of the
pulse, 5 us of timing per bin) and with a free scale of the other fold.

--near OFFSETS: the record against the same place OFFSETS deg off instead (OUT/near.md). --blind:
a second stage's prototype: from `diagnose`'s template fit on the record (angle, size) only, the
same search around the fit's angle and every branch fit + k 27.69 deg within 63 deg of the load
line, either side; the branch whose best run fits best, and by how much (OUT/blind.md).

--scatter: only the baselines (the same run acquired again, the same scene's next --length s),
over the whole fold and over the pulse's window (locate_outer.py's comparison): the margin's
calibration at that length (OUT/scatter_<L>_<fold period>.md). --length L: records
of L s instead of 0.3 (their runs under OUT/length<L>). --fold-period: diagnose's for every fold
(grid, the committed banks', or fine). --rate R: records acquired at R Hz instead of 20 kHz (the
bank then the committed bank_outer_radial_r<R>_low.txt unless --bank): the margin's calibration
at another rate (OUT/scatter_<L>_<fold period>_r<R>.md).

  studies/branch_check.py [--cases 30:0.5,30:1.5,...] [--seed 7] [--length 0.3] [--rate 20000]
      [--fold-period grid|fine] [--near OFFSETS | --blind | --scatter] OUT

Writes OUT/branch.csv, OUT/branch.md and OUT/profile_<theta>_<size>.txt (the two folds and the
standard error per bin); runs and acquisitions are cached under OUT.
"""
import argparse
import math
import os
import sys

import numpy as np

import common
import fold_compare
import sizing
import template_bank
from fold_compare import bank_best_size, chi2_noise, compare, read_bank, read_fold, shifted

NOISE, SEED = "low", 7
# the records' rate (Hz; --rate): 20 kHz, as the committed bank's
RATE = 2e4


def bank_at(rate):
    """The committed first-stage bank of outer pits under the radial load at this rate."""
    return os.path.join(common.DOC, "report", "sizing", "template",
                        f"bank_outer_radial_r{rate:g}_low.txt")


NB = 13
SPACING = 360.0 / NB
CASES = [(30.0, 0.5), (30.0, 1.5), (30.0, 3.0), (45.0, 0.5), (45.0, 1.5), (45.0, 3.0)]


# the record's length (s; --length): the folds' window from T_FROM
LENGTH = 0.3
# diagnose's --fold-period for every fold (--fold-period): grid, as the committed banks', or fine
FOLD_PERIOD = "grid"


def folded(out, size, angle, seed, later=0.0):
    """The run (pit `angle` deg from the load), acquired (seed) and folded: (y, se), the path.
    later = LENGTH: the same scene's next LENGTH s (a run to T_FROM + 2 LENGTH, folded from
    T_FROM + LENGTH, under out/later): an independent realization of the passes' scatter, where
    the record's own run acquired again repeats it. Records of another length than 0.3 s under
    out/length<L> (the runs' folders do not name their end)."""
    if LENGTH != 0.3:
        out = os.path.join(out, f"length{LENGTH:g}")
    if later:
        out = os.path.join(out, "later")
    sim, acq = template_bank.acquired(out, "outer", size, "radial", angle, RATE, NOISE, seed=seed,
                                      tend=sizing.T_FROM + LENGTH + later, allow_fail=False)
    path = acq[:-4] + ("" if FOLD_PERIOD == "grid" else "." + FOLD_PERIOD) + ".fold"
    if not os.path.exists(path):
        common.post(["diagnose", "--no-size", "--format", "json", "--column", "V", "--metadata",
                     os.path.join(sim, "run.json"), "--from", repr(sizing.T_FROM + later),
                     "--assume-defect", "outer", "--fold-period", FOLD_PERIOD,
                     "--pulse-fold-out", path, acq],
                    who="branch_check")
    return read_fold(path)


prep = fold_compare.prepared


def search(out, rec, bin_s, start, sizes0, seed, runs):
    """fold_compare.search() over this study's runs (acquisition seed + 1)."""
    return fold_compare.search(
        lambda ang, sz: chi2_noise(rec, prep(folded(out, sz, ang, seed + 1)), bin_s),
        start, sizes0, runs)


def case(out, bank, bin_s, angle, size, seed):
    """One case's numbers, and the fold profiles (t us, record, other place, se)."""
    other = round(angle - SPACING, 2)
    rec = prep(folded(out, size, angle, seed))
    noise = prep(folded(out, size, angle, seed + 1))  # the same run, other acquisition noise
    indep = prep(folded(out, size, angle, seed + 1, later=LENGTH))  # the same scene, next LENGTH
    ctl = prep(folded(out, round(size * 1.04, 3), angle, seed + 1))
    s0 = bank_best_size(bank, bin_s, rec, other)
    runs = {}  # (angle, size) -> chi2
    best_chi2, alt_size, ang = search(out, rec, bin_s, other, [s0, size], seed, runs)
    best_size = alt_size
    alt = prep(folded(out, alt_size, ang, seed + 1))
    other_runs = " ".join(f"{a_:g}/{x:g}" for a_, x in sorted(runs))
    d = compare(rec, alt, bin_s)
    n = d["n"]
    c_acq = chi2_noise(rec, noise, bin_s)
    c_noise = chi2_noise(rec, indep, bin_s)
    row = {"angle_deg": angle, "size_deg": size, "other_angle_deg": ang,
           "other_size_deg": round(best_size, 3), "runs_other": other_runs,
           "chi2_at_spacing": min(v for (a_, x), v in runs.items() if a_ == round(other, 2)),
           "peak": float(np.max(rec[0])), "se_median": float(np.median(rec[1])), "bins": n,
           "chi2_acquisition": c_acq, "chi2_noise": c_noise, "chi2_other": best_chi2,
           "dprime_other": math.sqrt(max(best_chi2 - c_noise, 0.0)),
           "chi2_control": chi2_noise(rec, ctl, bin_s),
           "chi2_other_fit": compare(rec, alt, bin_s, model=True)["dprime"] ** 2,
           "chi2_other_free": compare(rec, alt, bin_s, scale_free=True)["dprime"] ** 2,
           "free_scale": compare(rec, alt, bin_s, scale_free=True)["scale"],
           "max_z": d["max"], "max_at_us": d["max_at_us"], "shift_us": d["shift_us"],
           "nearest_run_size": alt_size}
    # the profiles, the other place's aligned as compare() did
    yr, _ = shifted(rec[0], d["shift_us"] / (bin_s * 1e6))
    sr, _ = shifted(rec[1], d["shift_us"] / (bin_s * 1e6))
    prof = [((j - len(rec[0]) / 4) * bin_s * 1e6, yr[j], alt[0][j], math.hypot(sr[j], alt[1][j]))
            for j in range(n)]
    return row, prof


def near(a, bin_s):
    """chi2 of each case's record against the same place `offset` deg off, same size."""
    offsets = [float(v) for v in a.near.split(",")]
    lines = [f"`studies/branch_check.py --near {a.near} --cases {a.cases} --seed {a.seed} OUT`: "
             "chi2 of the record against the same place that far off (same size, seed "
             f"{a.seed + 1})", "", "| pit (deg from load, size) | " +
             " | ".join(f"{o:+g} deg" for o in offsets) + " |", "|---" * (len(offsets) + 1) + "|"]
    for c in a.cases.split(","):
        angle, size = (float(v) for v in c.split(":"))
        rec = prep(folded(a.out, size, angle, a.seed))
        cs = [chi2_noise(rec, prep(folded(a.out, size, angle + o, a.seed + 1)), bin_s)
              for o in offsets]
        lines.append(f"| {angle:g}, {size:g} | " + " | ".join(f"{v:.0f}" for v in cs) + " |")
        print(lines[-1], flush=True)
    with open(os.path.join(a.out, "near.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def blind(a, bank, bin_s):
    """For each case's record: diagnose's fit (angle, size), then search() at the fit's angle
    and one ball spacing either side (within the zone); the branches' best chi2."""
    import re
    import template_bank
    lines = [f"`studies/branch_check.py --blind --cases {a.cases} --seed {a.seed} OUT`: from "
             "`diagnose`'s template fit (angle, size) only, the best run around the fit's angle "
             "and every branch fit + k 27.69 deg within 63 deg of the load line, either side "
             f"(chi2 against the record; acquisition seed {a.seed}, the runs {a.seed + 1})", "",
             "| pit (deg from load, size) | fit (deg, size) | candidates: start -> best (deg, "
             "size) chi2 | picked | margin |", "|---" * 5 + "|"]
    for c in a.cases.split(","):
        angle, size = (float(v) for v in c.split(":"))
        place = round(90.0 + angle, 3)
        rec = prep(folded(a.out, size, angle, a.seed))
        sim = os.path.join(a.out, "sim", f"outer_{size:g}_radial_p{place:g}")
        acq = os.path.join(a.out, "acq", f"outer_{size:g}_radial_p{place:g}_r{RATE:g}_{NOISE}_"
                           f"s{a.seed}.txt")
        d = template_bank.diagnose(a.out, sim, acq, "outer", a.bank)
        m = re.search(r"template fit's angle from the load ([0-9.]+) deg",
                      d.get("position_note", ""))
        fit, fit_size = float(m.group(1)), float(d["size_deg"])
        found = []
        # every branch within the zone, either side of the load line (the phase's branches
        # theta + k 27.69, signed; the fit's angle stands in for theta)
        for start in (fit + k * SPACING for k in (-2, -1, 0, 1, 2)):
            if not -63 <= start <= 63:
                continue
            start = round(start, 2)
            runs = {}
            chi2, sz, ang = search(a.out, rec, bin_s, start, [round(fit_size, 3),
                                   round(bank_best_size(bank, bin_s, rec, start), 3)], a.seed, runs)
            found.append((chi2, start, ang, sz, len(runs)))
        found.sort()
        margin = found[1][0] - found[0][0] if len(found) > 1 else float("nan")
        text = "; ".join(f"{st:g} -> {an:g}, {sz:g}: {ch:.0f} ({nr} runs)"
                         for ch, st, an, sz, nr in sorted(found, key=lambda f: f[1]))
        lines.append(f"| {angle:g}, {size:g} | {fit:g}, {fit_size:.3g} | {text} | "
                     f"{found[0][2]:g} | {margin:.0f} |")
        print(lines[-1], flush=True)
    with open(os.path.join(a.out, "blind.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def scatter(a, bin_s):
    """The margin's calibration at the record's length: for each case, chi2 of the record
    against the same run acquired again (the instrument's noise) and against the same scene's
    next LENGTH s (an independent realization), as the full study's baselines, without the
    other branch's search, over the whole fold and over the pulse's window with a line fitted
    (fold_compare.pulse_window(): locate_outer.py's comparison, whose margin this calibrates)
    (OUT/scatter_<length>_<fold period>[_r<rate>].md)."""
    rate = "" if RATE == 2e4 else f" --rate {RATE:g}"
    lines = [f"# The margin's calibration: two realizations of one scene ({LENGTH:g} s, "
             f"{FOLD_PERIOD} folds)", "",
             f"Regenerated at {common.made_at()} by `studies/branch_check.py --scatter --length {LENGTH:g} --fold-period "
             f"{FOLD_PERIOD}{rate} --cases {a.cases} --seed {a.seed} OUT` ({RATE / 1e3:g} kHz, "
             "16 bits, low noise): "
             f"chi2 of the record ({LENGTH:g} s, acquisition seed {a.seed}) against the same run "
             f"acquired again (seed {a.seed + 1}) and against the same scene's next {LENGTH:g} s "
             f"(seed {a.seed + 1}), over the whole fold and over the pulse's window (from 0.1 "
             "period before the entry to 0.25 after, a line fitted: studies/locate_outer.py's "
             "comparison)", "",
             "| pit (deg from load, size) | bins | chi2: same run, other acquisition noise | "
             f"chi2: same scene, next {LENGTH:g} s | bins in the window | the window's chi2: "
             f"same run | the window's chi2: next {LENGTH:g} s |", "|---" * 7 + "|"]
    worst = [0.0, 0.0]
    for c in a.cases.split(","):
        angle, size = (float(v) for v in c.split(":"))
        rec = prep(folded(a.out, size, angle, a.seed))
        again = prep(folded(a.out, size, angle, a.seed + 1))
        later = prep(folded(a.out, size, angle, a.seed + 1, later=LENGTH))
        window = fold_compare.pulse_window(size, NB)
        row = [f"{angle:g}, {size:g}"]
        for k, w in enumerate((None, window)):
            c_acq = chi2_noise(rec, again, bin_s, w)
            c_next = chi2_noise(rec, later, bin_s, w)
            worst[k] = max(worst[k], c_next)
            row += [str(fold_compare.compared_bins(rec, later, w)), f"{c_acq:.2g}",
                    f"{c_next:.0f}"]
        lines.append("| " + " | ".join(row) + " |")
        print(lines[-1], flush=True)
    lines += ["", f"Largest chi2 between two realizations: {worst[0]:.0f} over the whole fold, "
              f"{worst[1]:.0f} in the pulse's window."]
    tag = "" if RATE == 2e4 else f"_r{RATE:g}"
    with open(os.path.join(a.out, f"scatter_{LENGTH:g}_{FOLD_PERIOD}{tag}.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def main(argv):
    global LENGTH, FOLD_PERIOD, RATE
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", default=",".join(f"{a:g}:{s:g}" for a, s in CASES),
                    help="ANGLE:SIZE pairs (deg from the load, deg)")
    ap.add_argument("--seed", type=int, default=SEED)
    ap.add_argument("--bank", help="the first stage's bank (default: the committed one at --rate)")
    ap.add_argument("--rate", type=float, default=RATE,
                    help="the records' rate (Hz; default 20000, the committed bank's)")
    ap.add_argument("--near", default="",
                    help="OFFSETS (deg, e.g. -1.25,-0.5,0.5,1.25): also the same place that far "
                    "off, same size (OUT/near.md): how fast the fold changes on the true branch")
    ap.add_argument("--blind", action="store_true",
                    help="a second stage's prototype: from `diagnose`'s fit angle and size only, "
                    "the search around it and one spacing either side; the branch whose best "
                    "run fits best (OUT/blind.md)")
    ap.add_argument("--scatter", action="store_true",
                    help="only the baselines: chi2 against the same run acquired again and the "
                    "same scene's next --length s, per case (OUT/scatter_L_P.md): the margin's "
                    "calibration at that length")
    ap.add_argument("--length", type=float, default=LENGTH,
                    help="the record's length (s, from 0.05 s; default 0.3)")
    ap.add_argument("--fold-period", choices=("grid", "fine"), default=FOLD_PERIOD,
                    help="diagnose's --fold-period for every fold (default grid, as the banks')")
    ap.add_argument("out")
    a = ap.parse_args(argv)
    if not 0.05 <= a.length <= 10:
        sys.exit(f"branch_check: --length expects seconds in [0.05, 10], got {a.length:g}")
    LENGTH, FOLD_PERIOD, RATE = a.length, a.fold_period, a.rate
    a.bank = a.bank or bank_at(RATE)
    if not os.path.exists(a.bank):
        sys.exit(f"branch_check: no bank at --rate {RATE:g} ({a.bank}): give --bank FILE")
    bank, bin_s = read_bank(a.bank)
    if a.scatter:
        scatter(a, bin_s)
        return
    if a.near:
        near(a, bin_s)
        return
    if a.blind:
        blind(a, bank, bin_s)
        return
    cases = [tuple(float(v) for v in c.split(":")) for c in a.cases.split(",")]
    rows = []
    for angle, size in cases:
        row, prof = case(a.out, bank, bin_s, angle, size, a.seed)
        with open(os.path.join(a.out, f"profile_{angle:g}_{size:g}.txt"), "w") as f:
            f.write(f"# t_us record other({row['other_angle_deg']:g} deg, "
                    f"{row['nearest_run_size']:g} deg) se  (cycle removed, aligned)\n")
            for p in prof:
                f.write(" ".join(f"{v:.6g}" for v in p) + "\n")
        print(" ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}"
                       for k, v in row.items()), flush=True)
        rows.append(row)
    common.write_csv(os.path.join(a.out, "branch.csv"), rows)
    lines = ["# The outer pit's branch: one ball spacing apart", "",
             f"Regenerated at {common.made_at()} by `studies/branch_check.py --cases {a.cases} --seed {a.seed}"
             + ("" if RATE == 2e4 else f" --rate {RATE:g}") + " OUT` "
             f"({RATE / 1e3:g} kHz, 16 bits, low noise; the record at acquisition seed {a.seed}, "
             f"the other runs at {a.seed + 1}). chi2 over the fit's bins, in units of the folds' "
             "standard errors (the averaged pulse's); d' = sqrt(chi2 other - chi2 next 0.3 s): the "
             "difference beyond the scatter of the averaged pulse, in standard errors.", "",
             "| pit (deg from load, size) | other branch: best (deg, size; runs) | peak | median "
             "se | bins | chi2: same run, other acquisition noise | chi2: same scene, next 0.3 s "
             "| chi2: size +4 % | chi2: other branch at 27.7 deg nearer | chi2: other branch, "
             "best | d' | (chi2 other - next) / sqrt(2 bins) "
             "| chi2 other, fit's allowance | chi2 other, free scale | largest bin (se, us from "
             "entry) |", "|---" * 15 + "|"]
    for r in rows:
        lines.append(
            f"| {r['angle_deg']:g}, {r['size_deg']:g} | {r['other_angle_deg']:g}, "
            f"{r['other_size_deg']:g}; {len(r['runs_other'].split())} | {r['peak']:.3g} | "
            f"{r['se_median']:.2g} | {r['bins']} | {r['chi2_acquisition']:.2g} | "
            f"{r['chi2_noise']:.0f} | {r['chi2_control']:.0f} | {r['chi2_at_spacing']:.0f} | "
            f"{r['chi2_other']:.0f} | "
            f"{r['dprime_other']:.1f} | "
            f"{(r['chi2_other'] - r['chi2_noise']) / math.sqrt(2 * r['bins']):+.1f} | "
            f"{r['chi2_other_fit']:.0f} | {r['chi2_other_free']:.0f} ({r['free_scale']:.3f}) | "
            f"{r['max_z']:.1f} ({r['max_at_us']:+.0f}) |")
    with open(os.path.join(a.out, "branch.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1:])

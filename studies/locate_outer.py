#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Where an outer-race pit is, from the load direction: the second stage after
`ohmdem-post diagnose --size-method template`. EXPERIMENTAL: not part of `ohmdem-post size` or
`diagnose`, which place an outer pit modulo the ball spacing (and pick the branch only by the
template fit's angle, doc/post/size.md); its margins and p-value law below were calibrated on 16
held-out 20 kHz records (12 at 50 kHz) of one bearing, speed and load, and hold for no other
scene until measured there. Under a radial load diagnose places an outer pit
from its pulses' phase only modulo the ball spacing (360/Nb deg): a pit at theta and one at
theta - 360/Nb see the other balls in the same places as one crosses the pit. The branches differ
in which ball loses its load, and the simulator tells what that does to the pulse. This stage runs
the record's scene with the pit on each branch (the phase's interval moved by k 360/Nb, widened by
--window deg either side) within --zone deg of the load line, samples each branch's window for the
run whose fold (acquired through the record's own chain, as its header states it) is nearest the
record's (every 0.5 deg at the first stage's size, then the size 8 % apart at the two best angles,
then the angle to 0.25 deg: the misfit is too rugged in the angle to descend), refines the branches
within chi2 600 of the best to 1/8 deg and then 1/16 deg, the size again at each new angle; the
branches within the margin and 2 x 63 of the best are looked at again (one whose best run fits
worse than the margin, or than 50 per 68 bins of the window, every 0.25 deg over its window at
its best size, then each every 1/16 deg within 0.5 deg of its best run), and it keeps the branch
whose best run fits best, when it beats the runner-up by a chi2 margin of more than --margin, or,
on records like those its p-values were calibrated on (grid folds of up to 0.375 s at 20 and 50
kHz), when it is the one branch whose best run fits as the pit's own branch does (p >= 0.1) and
every other's p-value is below 0.01 (the chance that the pit's own branch fits as badly: from its
best run's chi2 on 16 held-out 20 kHz records, a chi2 per bin, checked on 12 at 50 kHz). The folds
are compared over the pulse's window (fold_compare.pulse_window(): from 0.1 period before the
entry to 0.25 after, a line fitted), where two realizations of one scene differ least; the margin
is the largest chi2 between two independent realizations of one scene there, over 51 scenes (pits
of 0.3-3 deg, -30 to 57.5 deg from the load line), at the record's rate
(doc/report/sizing/template/scatter_*.md: 230 at 10 kHz, 50 at 20 kHz, 1210 at 50 kHz). Else
the branch is not determined, and the candidates within the margin are listed; when they are two
mirror images about the load line (a pit about half a ball spacing from it), the pit's distance
from the load line is given. The record and the runs are folded at the grid's period up to
0.375 s of record and at the fine one beyond (--fold-period auto): the grid's smear, which
differs from window to window, outgrows the margin on long records (two realizations of 1.2 s,
over the whole fold: chi2 up to 1136 at the grid's period, 155 at the fine one, on 15 scenes).

  studies/locate_outer.py --metadata RUN_JSON [--bank FILE] [--from S] [--column V] [--deck DECK]
      [--var NAME VALUE ...] [--zone 63] [--margin CHI2] [--fold-period auto|grid|fine]
      [--seed 8] [--format json|text] [--window 2] [--keep-runs] RECORD OUT

RECORD: a record written by `ohmdem-post acquire` (its '#' header holds the chain: column,
scale, anti-alias low-pass, rate, noise, ADC). --metadata: the scene's run.json (bearing, speed,
load, force, ...), from which the deck's variables are set (--var adds or overrides one; the
deck: inputs/bearing_6208/in.bearing unless --deck). The runs, their acquisitions and folds are
kept under OUT (a second call reuses them; the runs' 1 MHz signals are deleted once acquired
unless --keep-runs); OUT/locate.json holds the answer, also printed.
About 30-40 runs of the scene a branch (4-5 branches within 63 deg on a 13-ball bearing; 120-240
a record, the second look adding about a fifth): 5-7 minutes on one core for the 6208's 0.3 s
records, 25-30 for 1.2 s ones.
doc/methods/place_outer_branch.md.
"""
import argparse
import json
import math
import os
import re
import sys

from scipy import stats

import common
import fold_compare

# in.bearing's radial load pushes the outer ring along -y: the balls at +y (90 deg on the race)
# carry it; diagnose's angles are from there, positive in the balls' direction of travel
ZONE_CENTRE_DEG = 90.0
# the margin by the folds' period and the record's rate (Hz): the largest chi2 between two
# independent realizations of one scene in the pulse's window (studies/branch_check.py --scatter,
# 51 scenes: doc/report/sizing/template/scatter_*.md), rounded up to a ten: at 20 kHz grid folds
# 44 at 0.3 s, fine folds 40 at 0.3 s and 73 at 1.2 s (over the whole fold: 345, 433 and 1402);
# at 50 kHz grid folds 1210 at 0.3 s (the 3 deg pit 30 deg from the load line; the other 50
# scenes up to 118): the wider anti-alias filter keeps the pit's edges, which differ between
# realizations by more than the passes' scatter within one; at 10 kHz grid folds 224 at 0.3 s
# (median 89, against 23 at 20 kHz): the scatter is not monotonic in the rate
MARGINS = {"grid": {1e4: 230.0, 2e4: 50.0, 5e4: 1210.0}, "fine": {2e4: 80.0}}
ZONE_DEG = 63.0
# each branch's runs lie within the phase's interval moved onto it, widened by this much either
# side (the phase's centroid lies up to 2.8 deg off the pit in heldout_angles*.md)
WINDOW_DEG = 2.0
# branches whose best scanned run lies within this chi2 of the best branch's (or 3 margins, if
# more) are refined (fold_compare.refine()): their best lies up to 0.25 deg off the scan's grid,
# which cost it up to a few hundred over the whole fold (chi2 296-956 at +-0.5 deg from the pit
# on the test's 1.5 deg pit), the span kept when the margins fell
REFINE_SPAN = 600.0
# the most a branch's least lay under what scan() and refine() found for it, over all the runs
# made on the six 1.2 s records of doc/report/sizing/template/locate_check_len1.2_window.md
# (one run per 1/16 deg is its own realization): the branches within the margin
# and twice this of the best are looked at again (fold_compare.rescan() and dense())
SEARCH_MISS = 63.0
# the best run's chi2 per bin beyond which no run of the scene is like the record (the records
# of branch.md and blind.md: 0.1-6.5 per bin at the true branch over the whole fold)
MAX_CHI2_PER_BIN = 20.0
# the pit's own branch: ln chi2 of its best run after the whole search (scan, refine, second
# look), over the 16 held-out 0.3 s records of doc/report/sizing/template/locate_check_rescan.csv
# and locate_check_s25{a,b,c}.csv (20 kHz, 16 bits, low noise, grid folds, the pulse's window; in
# all 16 the best run lay on the pit's branch): chi2 1.9-22.9, median 4.9, below one realization's
# scatter (median ~20) since the best of ~30-80 runs fits both the pit and the record's own
# realization; the logs' mean and sd (Shapiro-Wilk on them: p 0.61). A branch's p-value is the
# chance that the pit's own branch fits as badly or worse: Student's t with 15 degrees of freedom
# on the logs, the predictive distribution of one more record from 16. In units of the chi2 over
# the calibration's 68 bins of the pulse's window: a record folded into other bins is scaled to
# them (12 held-out 50 kHz records, 170 bins, their ln chi2 so scaled agree with the
# 16 (Welch's t p 0.86, Levene's p 0.095; unscaled Welch's p 0.019):
# doc/report/sizing/template/locate_check_r50000_s27{a,b}.csv)
OWN_BRANCH = {"mean": 1.607, "sd": 0.664, "records": 16, "bins": 68}
# the p-values hold for records like the calibration's: grid folds of up to GRID_LENGTH_S at
# these rates (elsewhere the margin decides alone)
CALIBRATED_RATES = (2e4, 5e4)
# a branch whose p-value is below REJECT_P is not the pit's: a placement on the one branch left is
# wrong only when the pit's own was rejected, in REJECT_P of records; the one left must fit as the
# pit's own usually does (p >= CONSISTENT_P), so that two branches near REJECT_P's chi2 (~30) do
# not decide on a difference of a few
REJECT_P = 0.01
CONSISTENT_P = 0.1
# grid folds: the length (s) up to which two realizations of a scene stay within the margin
# (0.3 s: 10-200 in branch.md; 1.2 s: up to 1136, the smear of the grid's period)
GRID_LENGTH_S = 0.375
# the lowest rate whose held-out records the margin was checked on (20 and 50 kHz: none placed on
# a wrong branch; at 10 kHz one of 12 was): below it a placement carries a caution
CHECKED_RATE = 2e4
# run.json -> in.bearing's variables (the scene; the pit's own are set per run)
SCENE = [("omega_input", "omega"), ("omega_start", "omega_start"), ("ramp", "ramp"),
         ("load", "load"), ("F_input", "F"), ("I", "I"), ("gamma", "gamma"), ("area", "area"),
         ("dt", "dt"), ("cage_clearance", "cclear"), ("cage_mass", "mcage"),
         ("ring_mass", "Mring"), ("ring_damping", "Cring"), ("t_sliding_end", "tslide"),
         ("depth", "depth"), ("lubricant", "lubricant"), ("temperature", "temperature"),
         ("roughness", "roughness"), ("fexc", "fexc"), ("wetted", "wetted")]
CUSTOM_GEOMETRY = [("nb", "Nb"), ("db", "Db"), ("dext", "Dext"), ("dinn", "Dinn"),
                   ("rc_ext", "Rcext"), ("rc_inn", "Rcinn")]


def fail(text):
    sys.exit(f"locate_outer: {text}")


def read_chain(path):
    """The acquisition chain a record's header states: the `ohmdem-post acquire` options that
    repeat it (without the seed), the analysis window (from, to) and the column's name."""
    head = fold_compare.read_header(path)
    # the columns' line ('# time V ...') has no colon: read_header keeps it as a key
    columns = next((k.split() for k in head if k.startswith("time ")), [])
    if "chain" not in head:
        fail(f"{path}: no '# chain:' line: RECORD must be a record written by "
             "`ohmdem-post acquire` (its header states the chain)")

    def need(key, pattern):
        m = re.match(pattern, head.get(key, ""))
        if not m:
            fail(f"{path}: the header's '# {key}:' line is missing or unreadable (expected "
                 f"'{pattern}', got '{head.get(key, '')}')")
        return m

    column = head.get("input column", "")
    if not column:
        fail(f"{path}: no '# input column:' line")
    window = need("input window", r"([-+0-9.eE]+) to ([-+0-9.eE]+) s")
    args = ["--column", column, "--scale", need("scale", r"([-+0-9.eE]+)").group(1),
            "--offset", need("offset", r"([-+0-9.eE]+)").group(1),
            "--rate", need("sampling rate (Hz)", r"([-+0-9.eE]+)").group(1)]
    lp = head.get("lowpass", "")
    if lp != "none":
        m = need("lowpass", r"Butterworth order (\d+), cut-off ([-+0-9.eE]+) Hz.*, (steady|zero) "
                 "initial state")
        args += ["--lowpass", m.group(2), "--order", m.group(1), "--filter-start", m.group(3)]
    if head.get("noise", "") != "none":
        args += ["--noise-rms", need("noise", r"white Gaussian added to the samples, rms "
                                     r"([-+0-9.eE]+)").group(1)]
    if head.get("adc", "") != "none":
        m = need("adc", r"(\d+) bits, range ([-+0-9.eE]+) to ([-+0-9.eE]+),")
        args += ["--bits", m.group(1), "--range", m.group(2), m.group(3)]
    name = columns[1] if len(columns) > 1 else "V"
    args += ["--name", name]
    if head.get("unit"):
        args += ["--unit", head["unit"]]
    return args, float(window.group(1)), float(window.group(2)), name


def scene_variables(meta):
    """in.bearing's -var values for the run.json's scene."""
    if meta.get("load") != "radial":
        fail(f"the scene's load is '{meta.get('load')}': an outer pit's branch exists under "
             "load radial only (the other loads load every ball alike)")
    v = {"bearing": meta.get("catalog_name", meta.get("bearing", "machado2014"))}
    for key, var in SCENE:
        if key in meta:
            v[var] = meta[key]
    if v["bearing"] == "custom":
        for key, var in CUSTOM_GEOMETRY:
            v[var] = meta[key]
    return v


class Scene:
    """Runs of the record's scene with an outer pit (size, angle from the load), acquired
    through the record's chain and folded; cached under OUT."""

    def __init__(self, a, chain, t_from, t_to, name, variables):
        self.a, self.chain, self.t_from, self.name = a, chain, t_from, name
        self.vars = dict(variables, **dict(a.var))
        self.tend = t_to
        self.runs = 0

    def fold(self, angle, size):
        tag = f"outer_{size:g}_a{angle:g}"
        sim = os.path.join(self.a.out, "runs", tag)
        if not common.finished(sim):
            os.makedirs(sim, exist_ok=True)
            values = dict(self.vars, defect="outer", size=size,
                          position=round(ZONE_CENTRE_DEG + angle, 3), tend=self.tend)
            common.run(common.deck_command(self.a.deck, [
                "-var", "out", sim, "-log", os.path.join(sim, "log.liggghts"), "-screen", "none"]
                + common.variables(values)), os.path.join(sim, "stdout.txt"), who="locate_outer")
            self.runs += 1
        acq = os.path.join(sim, f"acq_s{self.a.seed}.txt")
        if not os.path.exists(acq):
            common.post(["acquire", "--from", repr(self.t_from), "--seed", str(self.a.seed)]
                        + self.chain + ["--output", acq + ".part",
                                        os.path.join(sim, "signal.txt")], who="locate_outer")
            os.replace(acq + ".part", acq)
            if not self.a.keep_runs:  # the 1 MHz signal and restart files: ~100 MB a run
                for f in os.listdir(sim):
                    if f == "signal.txt" or f.startswith("restart."):
                        os.remove(os.path.join(sim, f))
        path = acq[:-4] + ("" if self.a.fold_period == "grid" else ".fine") + ".fold"
        if not os.path.exists(path) and not os.path.exists(path + ".none"):
            r = common.post(["diagnose", "--no-size", "--format", "json", "--column", self.name,
                             "--metadata", os.path.join(sim, "run.json"), "--from",
                             repr(self.t_from), "--assume-defect", "outer", "--fold-period",
                             self.a.fold_period, "--pulse-fold-out", path + ".part", acq],
                            who="locate_outer", allow_fail=True)
            if r.returncode != 0:
                # a run the chain cannot fold (its period a near whole number of samples, as
                # studies/template_bank.py skips): no fold, said once and kept
                with open(path + ".none", "w") as f:
                    f.write(r.stderr)
                print(f"locate_outer: no fold of the run {tag}: {r.stderr.strip()}",
                      file=sys.stderr)
                return None
            os.replace(path + ".part", path)
        if os.path.exists(path + ".none"):
            return None
        return fold_compare.prepared(fold_compare.read_fold(path))


def first_stage(a, record_fold):
    """diagnose's template fit on the record: its JSON (the record's fold as the bank's, for
    the branches' starting sizes)."""
    args = ["diagnose", "--format", "json", "--column", a.column, "--metadata", a.metadata,
            "--from", repr(a.t_from), "--assume-defect", "outer", "--pulse-fold-out", record_fold]
    if a.bank:
        args += ["--size-method", "template", "--template-bank", a.bank]
    return json.loads(common.post(args + [a.record], who="locate_outer").stdout)


def record_fold_as_runs(a, path):
    """The record folded as the runs are (--fold-period), for the comparisons."""
    common.post(["diagnose", "--no-size", "--format", "json", "--column", a.column, "--metadata",
                 a.metadata, "--from", repr(a.t_from), "--assume-defect", "outer",
                 "--fold-period", a.fold_period, "--pulse-fold-out", path, a.record],
                who="locate_outer")


def own_branch_p(chi2, own=None, bins=None):
    """The p-value of a branch whose best run has this chi2 over `bins` bins (the calibration's
    unless given): the chance that the pit's own branch fits as badly or worse (own: the
    calibration, OWN_BRANCH unless given)."""
    own = own or OWN_BRANCH
    if chi2 <= 0:
        return 1.0
    if bins:
        chi2 *= own.get("bins", OWN_BRANCH["bins"]) / bins
    n = own["records"]
    z = (math.log(chi2) - own["mean"]) / (own["sd"] * math.sqrt(1 + 1 / n))
    return float(stats.t.sf(z, n - 1))


def p_values_hold(fold_period, rate, length_s):
    """Whether own_branch_p() is calibrated for a record with this chain: grid folds of up to
    GRID_LENGTH_S at one of CALIBRATED_RATES."""
    return (fold_period == "grid" and length_s <= GRID_LENGTH_S
            and any(abs(rate - r) <= 1e-6 * r for r in CALIBRATED_RATES))


def decide(found, margin, bins, spacing, p_values=False):
    """The branch from each candidate's best run: found = [(chi2, branch, angle, size, runs)];
    by the margin, and with p_values (own_branch_p()) also when every other branch fits worse
    than the pit's own branch does in all but REJECT_P of records. Returns (whether the best of
    `found` by chi2 is placed, the note)."""
    found = sorted(found)
    best = found[0]
    if best[0] / bins > MAX_CHI2_PER_BIN:
        return False, (f"not determined: no run of the scene folds like the record (the best, "
                       f"{best[2]:g} deg and {best[3]:g} deg of pit, has chi2 {best[0]:.0f} over "
                       f"{bins} bins, more than {MAX_CHI2_PER_BIN:g} a bin): another scene?")
    if len(found) == 1:
        return True, "the only branch within the zone"
    gap = found[1][0] - best[0]
    if gap > margin:
        return True, (f"the branch whose best run fits best, by a chi2 margin of {gap:.0f} "
                      f"(> {margin:g}) over the branch at {found[1][1]:g} deg")
    ps = [own_branch_p(f[0], bins=bins) for f in found] if p_values else []
    if ps and ps[0] >= CONSISTENT_P and max(ps[1:]) < REJECT_P:
        return True, (f"the only branch whose best run fits as the pit's own branch does (p "
                      f"{ps[0]:.2g}); every other fits worse than the pit's own in all but "
                      f"{REJECT_P:.0%} of records (the next, at {found[1][1]:g} deg: chi2 "
                      f"{found[1][0]:.0f}, p {ps[1]:.1g})")
    close = [f for f in found if f[0] - best[0] <= margin]
    note = ("not determined: the branches at " + ", ".join(f"{f[1]:g}" for f in close) +
            f" deg fit within a chi2 margin of {margin:g} (the scatter of an independent "
            f"realization of the same record reaches it)")
    if ps:
        note += ("; their p-values " + ", ".join(f"{p:.2g}" for p in ps[:len(close)]) +
                 f" (placed when the best's >= {CONSISTENT_P:g} and every other's < {REJECT_P:g})")
    return False, note + f"; modulo the ball spacing {spacing:.4g} deg"


def margin_at(fold_period, rate):
    """The margin for folds of this period on a record at this rate (Hz), and whether that pair
    was calibrated. Else the larger of the calibrations at the calibrated rates on either side
    of it (the one beyond the end when it lies outside them): the scatter between realizations
    is not monotonic in the rate (10 kHz's is above 20 kHz's), so neither neighbour alone
    bounds it. At a rate where the period has no calibration of its own, the largest of the
    periods' there."""
    own = MARGINS[fold_period]
    rates = sorted({r for m in MARGINS.values() for r in m})
    calibrated = [r for r in own if abs(r - rate) <= 1e-6 * r]
    if calibrated:
        return own[calibrated[0]], True
    below = [r for r in rates if r <= rate * (1 + 1e-6)][-1:]
    above = [r for r in rates if r >= rate * (1 - 1e-6)][:1]

    def at(r):
        return own[r] if r in own else max(m[r] for m in MARGINS.values() if r in m)
    return max(at(r) for r in below + above), False


def fold_and_margin(length_s, fold_period, margin, rate=2e4):
    """The folds' period for a record of length_s (auto: grid up to GRID_LENGTH_S, as checked
    on held-out records; fine beyond, where the grid's smear outgrows the
    margin) and the margin (margin_at() that period and rate unless given)."""
    if fold_period == "auto":
        fold_period = "grid" if length_s <= GRID_LENGTH_S else "fine"
    return fold_period, margin_at(fold_period, rate)[0] if margin is None else margin


def rescan_above(fold_period, margin, bins):
    """The chi2 above which a branch's best run is looked at again over its whole window: worse
    than the margin, and than the 20 kHz margin per bin of the pulse's window (the pit's own
    branch fits alike per bin at 20 and 50 kHz, OWN_BRANCH; the 50 kHz margin, 1210, is set by
    one large pit's realizations and would leave a branch's best at chi2 212 where its pit fits
    at 5 unsearched)."""
    per_bin = MARGINS[fold_period][2e4] * max(1.0, bins / OWN_BRANCH["bins"])
    return min(margin, per_bin)


def close_branches(found, margin, bins=None):
    """The candidates left when no branch is placed, best first: the best and the branches
    within the margin of it; with bins (the p-values calibrated), not those whose p-value is
    below REJECT_P (they fit worse than the pit's own branch does in all but REJECT_P of
    records)."""
    found = sorted(found)
    return found[:1] + [f for f in found[1:] if f[0] - found[0][0] <= margin
                        and (bins is None or own_branch_p(f[0], bins=bins) >= REJECT_P)]


def mirror_pair(found, margin, bins=None):
    """The best runs' angles when the branches left (close_branches()) are two whose best runs
    are mirror images about the load line (within ANGLE_STEP): a pit at about half the ball
    spacing from it, where the phase has a branch on either side at the same distance, which a
    symmetric radial load does not tell apart. None otherwise."""
    close = close_branches(found, margin, bins)
    if len(close) == 2 and abs(close[0][2] + close[1][2]) <= fold_compare.ANGLE_STEP:
        return close[0][2], close[1][2]
    return None


def branch_interval(at, phase, interval, spacing):
    """The interval of a best run at `at` deg: the phase's interval moved onto its branch,
    widened to the run's angle +- ANGLE_STEP (the phase's centroid lies up to ~2-3 deg off the
    pit on the held-out cases)."""
    k = round((at - phase) / spacing) * spacing
    return [min(interval[0] + k, at - fold_compare.ANGLE_STEP),
            max(interval[1] + k, at + fold_compare.ANGLE_STEP)]


def distance_from_load(found, margin, bins, spacing, phase, interval, p_values=False):
    """When no branch is placed: the pit's distance from the load line, either side (deg), by
    its best run, and the interval that holds every branch left (close_branches()). The radial
    load is symmetric about its line, so the branches that fit alike are mostly the pit's own
    and the one nearest its mirror image (on the 7 held-out 20 kHz records not placed, the
    best run within 0.61 deg of the pit's distance: locate_check_s29_not_placed.md in
    doc/report/sizing/template); where two branches at unlike distances are left, the interval
    spans both. None when no run is like the record (decide()) or, with
    p_values, when the best run itself is rejected."""
    close = close_branches(found, margin, bins if p_values else None)
    if close[0][0] / bins > MAX_CHI2_PER_BIN or (
            p_values and own_branch_p(close[0][0], bins=bins) < REJECT_P):
        return None
    ends = []
    for f in close:
        lo, hi = branch_interval(f[2], phase, interval, spacing)
        ends += [0.0 if lo <= 0 <= hi else min(abs(lo), abs(hi)), max(abs(lo), abs(hi))]
    return abs(close[0][2]), [min(ends), max(ends)]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("record")
    ap.add_argument("out")
    ap.add_argument("--metadata", required=True, help="the scene's run.json")
    ap.add_argument("--bank", default=os.path.join(
        common.DOC, "report", "sizing", "template", "bank_outer_radial_r20000_low.txt"),
        help="diagnose's --template-bank for the first stage's size ('' for none)")
    ap.add_argument("--from", dest="t_from", type=float, default=None,
                    help="start of the analysis (s; default: the record's first sample)")
    ap.add_argument("--column", default=None, help="the record's column (default: its own)")
    ap.add_argument("--deck", default=common.BEARING_DECK)
    ap.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    ap.add_argument("--zone", type=float, default=ZONE_DEG,
                    help="branches within this many deg of the load line")
    ap.add_argument("--margin", type=float, default=None,
                    help="the chi2 margin (default: the calibration for the folds' period and the "
                    "record's rate: 50 for grid folds, 80 for fine ones at 20 kHz; 1210 for grid "
                    "folds at 50 kHz, 230 at 10 kHz)")
    ap.add_argument("--seed", type=int, default=8, help="the runs' acquisition noise seed")
    ap.add_argument("--format", choices=("json", "text"), default="json")
    ap.add_argument("--keep-runs", action="store_true",
                    help="keep each run's signal and restart files (~100 MB a run)")
    ap.add_argument("--fold-period", choices=("auto", "fine", "grid"), default="auto",
                    help="how the record and the runs are folded for the comparisons (diagnose's "
                    "--fold-period): auto (default) grid up to %g s of record (as checked on "
                    "held-out records), fine beyond (the grid's smear outgrows "
                    "the margin there)" % GRID_LENGTH_S)
    ap.add_argument("--window", type=float, default=WINDOW_DEG,
                    help="deg added either side of the phase's interval on each branch")
    a = ap.parse_args(argv)
    for path, what in ((a.record, "RECORD"), (a.metadata, "--metadata"), (a.deck, "--deck")):
        if not os.path.isfile(path):
            fail(f"{what}: no such file '{path}'")
    if a.bank and not os.path.isfile(a.bank):
        fail(f"--bank: no such file '{a.bank}'")
    if not (a.zone > 0 and (a.margin is None or a.margin >= 0) and a.window >= 0):
        fail("--zone expects deg > 0, --margin a chi2 >= 0 and --window deg >= 0")
    chain, start, end, name = read_chain(a.record)
    a.t_from = start if a.t_from is None else a.t_from
    rate = float(chain[chain.index("--rate") + 1])
    margin_given = a.margin is not None
    a.fold_period, a.margin = fold_and_margin(end - a.t_from, a.fold_period, a.margin, rate)
    a.column = a.column or name
    with open(a.metadata) as f:
        meta = json.load(f)
    variables = scene_variables(meta)
    os.makedirs(a.out, exist_ok=True)
    record_fold = os.path.join(a.out, "record.fold")
    d = first_stage(a, record_fold)
    nb = int(meta.get("nb", 0))
    if d.get("position_reference") != "load direction" or d.get("position_deg") is None or nb < 2:
        fail("diagnose gives no outer pit's angle from the load direction for this record: "
             + str(d.get("position_note", d.get("size_note", ""))))
    spacing = 360.0 / nb
    phase = float(d["position_deg"])
    lo, hi = d.get("position_interval_deg") or [phase, phase]
    # the bank's starting sizes compare the bank with the record folded as the bank was (the
    # first stage's fold); the runs, the record folded as they are
    rec_bank = fold_compare.prepared(fold_compare.read_fold(record_fold))
    record_fold = os.path.join(a.out, f"record.{a.fold_period}.fold")
    record_fold_as_runs(a, record_fold)
    rec = fold_compare.prepared(fold_compare.read_fold(record_fold))
    bin_s = fold_compare.read_header(record_fold).get("bin (s)")
    if bin_s is None:
        fail(f"{record_fold}: diagnose's fold states no '# bin (s):'")
    bin_s = float(bin_s)
    scene = Scene(a, chain, a.t_from, end, a.column, variables)
    bank = fold_compare.read_bank(a.bank)[0] if a.bank else None
    size0 = d.get("size_deg")
    if size0 is None and bank is None:
        fail("the first stage gives no size to begin the runs at (" +
             str(d.get("size_note", d.get("size_method", ""))) + "): give a --bank for the "
             "record's chain (studies/template_bank.py writes one)")
    # the folds are compared over the pulse's window, for the first stage's size (else the bank's
    # largest: a window too long only adds bins)
    size_w = size0 if size0 is not None else max(k[0] for k in bank)
    window = fold_compare.pulse_window(size_w, nb)
    bins = fold_compare.compared_bins(rec, rec, window)
    half = 0.5 * (hi - lo) + a.window
    ks = [k for k in range(-nb, nb + 1) if abs(phase + k * spacing) <= a.zone]
    if not ks:
        fail(f"no branch of the phase {phase:g} deg lies within --zone {a.zone:g} deg")
    found, branches = [], {}
    for k in ks:
        centre = 0.5 * (lo + hi) + k * spacing
        # the sizes to begin with: the first stage's (fitted over the bank's angles: within ~6 %
        # on the held-out cases) and, when it differs by more than 15 %, the bank's best at the
        # branch's angle (another branch's best run may be 0.3-1.4 times the pit's size in
        # branch.md): so that every branch is searched from a size fit for it
        sizes0 = [size0] if size0 is not None else []
        if bank:
            own = fold_compare.bank_best_size(bank, bin_s, rec_bank, abs(centre))
            if size0 is None or abs(math.log(own / size0)) > math.log(1.15):
                sizes0.append(own)
        runs = {}

        def chi2_at(ang, sz, runs=runs):
            if (ang, sz) not in runs:
                fo = scene.fold(ang, sz)  # None: a run without a fold counts as no fit
                runs[(ang, sz)] = (math.inf if fo is None else
                                   fold_compare.chi2_noise(rec, fo, bin_s, window))
            return runs[(ang, sz)]
        chi2, sz, ang = fold_compare.scan(chi2_at, centre - half, centre + half, sizes0)
        branches[round(centre, 2)] = (chi2_at, runs, centre - half, centre + half)
        found.append((chi2, round(centre, 2), ang, sz, len(runs)))
        print(f"locate_outer: branch {centre:.2f} deg: best run {ang:g} deg, {sz:g} deg of pit, "
              f"chi2 {chi2:.0f} ({len(runs)} runs)", file=sys.stderr, flush=True)
    # The branches that may still win, refined to finer angles than the scan's grid: a branch's
    # best sampled run lies up to 0.25 deg off its minimum, which costs it up to a few hundred
    best = min(found)[0]
    for i, (chi2, centre, ang, sz, _) in enumerate(found):
        if chi2 - best <= max(REFINE_SPAN, 3 * a.margin):
            chi2_at, runs, b_lo, b_hi = branches[centre]
            chi2, sz, ang = fold_compare.refine(chi2_at, (chi2, sz, ang), b_lo, b_hi)
            found[i] = (chi2, centre, ang, sz, len(runs))
            print(f"locate_outer: branch {centre:.2f} deg refined: best run {ang:g} deg, {sz:g} "
                  f"deg of pit, chi2 {chi2:.0f} ({len(runs)} runs)", file=sys.stderr, flush=True)
    # The branches that may still decide the gap, looked at again, the best branch as the
    # runner-up: one whose best run fits worse than the margin (unlike any realization of the
    # record) over its whole window at its best size, since scan() sampled the angles at a size
    # that may be off the pit's; then each densely around its best, since refine()'s walk can
    # stop on a local minimum of the rugged misfit, up to SEARCH_MISS above the branch's least
    best = min(found)[0]
    unlike = rescan_above(a.fold_period, a.margin, bins)
    for i, (chi2, centre, ang, sz, _) in enumerate(found):
        if chi2 - best <= a.margin + 2 * SEARCH_MISS:
            chi2_at, runs, b_lo, b_hi = branches[centre]
            if chi2 > unlike:
                chi2, sz, ang = fold_compare.rescan(chi2_at, (chi2, sz, ang), b_lo, b_hi)
            chi2, sz, ang = fold_compare.dense(chi2_at, (chi2, sz, ang), b_lo, b_hi)
            found[i] = (chi2, centre, ang, sz, len(runs))
            print(f"locate_outer: branch {centre:.2f} deg looked at again: best run {ang:g} "
                  f"deg, {sz:g} deg of pit, chi2 {chi2:.0f} ({len(runs)} runs)", file=sys.stderr,
                  flush=True)
    # No branch fits like a realization of the record (the best worse than the margin): the
    # searches likely began far from the pit's size (the 10 kHz held-out -21.25/2.6: the first
    # stage read 4.77 deg, the bank's best at the branch's angle 0.59; the pit's own branch
    # fits at chi2 1.4 at 2.6 deg, where its search found 982 at 1.28 and another branch 825).
    # Each branch within reach, the size swept over the bank's sizes at its best angle
    best = min(found)[0]
    if best > a.margin:
        sizes = [k[0] for k in bank] if bank else [0.5 * size0, 2 * size0]
        for i, (chi2, centre, ang, sz, _) in enumerate(found):
            if chi2 - best <= a.margin + 2 * SEARCH_MISS:
                chi2_at, runs, b_lo, b_hi = branches[centre]
                chi2, sz, ang = fold_compare.sweep(chi2_at, (chi2, sz, ang), b_lo, b_hi,
                                                   min(sizes), max(sizes))
                found[i] = (chi2, centre, ang, sz, len(runs))
                print(f"locate_outer: branch {centre:.2f} deg, the size swept: best run {ang:g} "
                      f"deg, {sz:g} deg of pit, chi2 {chi2:.0f} ({len(runs)} runs)",
                      file=sys.stderr, flush=True)
    calibrated = p_values_hold(a.fold_period, rate, end - a.t_from)
    placed, note = decide(found, a.margin, bins, spacing, p_values=calibrated)
    if placed and rate < CHECKED_RATE:
        note += (f"; caution: below {CHECKED_RATE / 1e3:g} kHz the margin does not hold (at 10 kHz "
                 "one of 12 held-out pits was placed a ball spacing off: doc/methods/place_outer_branch.md)")
    if placed and rate >= CHECKED_RATE and not (margin_given or margin_at(a.fold_period, rate)[1]):
        note += (f"; caution: the margin ({a.margin:g}) was not calibrated for {a.fold_period} "
                 f"folds at {rate / 1e3:g} kHz: the larger of the calibrations on either side of "
                 "it (the scatter between realizations is not monotonic in the rate)")
    if placed and a.fold_period == "grid" and end - a.t_from > GRID_LENGTH_S:
        note += (f"; caution: folds at the grid's period on a record longer than "
                 f"{GRID_LENGTH_S:g} s differ by their smear beyond the margin "
                 "(doc/methods/place_outer_branch.md)")
    ordered = sorted(found)
    result = {"position_reference": "load direction", "fold_period": a.fold_period,
              "record_length_s": round(end - a.t_from, 6), "phase_deg": phase,
              "phase_interval_deg": [lo, hi], "ball_spacing_deg": spacing,
              "window_deg": [-half, half],
              "first_stage_size_deg": d.get("size_deg"), "margin": a.margin, "bins": bins,
              "pulse_window": [round(v, 4) for v in window],
              "candidates": [{"branch_deg": f[1], "best_run_deg": f[2], "best_run_size_deg": f[3],
                              "chi2": round(f[0], 3), "runs": f[4],
                              "p_value": own_branch_p(f[0], bins=bins) if calibrated else None}
                             for f in sorted(found, key=lambda f: f[1])],
              "p_values_calibrated": calibrated,
              "runs_made": scene.runs}
    if not placed:
        result.update(position_deg=None, position_interval_deg=None, branch_determined=False,
                      position_modulo_deg=spacing, distance_from_load_deg=None,
                      distance_interval_deg=None)
        dist = distance_from_load(found, a.margin, bins, spacing, phase, (lo, hi), calibrated)
        pair = mirror_pair(found, a.margin, bins if calibrated else None)
        if pair:
            result.update(mirror_positions_deg=list(pair))
            note += ("; the two are mirror images about the load line: on a side a symmetric "
                     "radial load does not tell")
        if dist:
            result.update(distance_from_load_deg=round(dist[0], 3),
                          distance_interval_deg=[round(v, 3) for v in dist[1]])
            note += (f"; the pit lies {dist[0]:.2f} deg from the load line, either side "
                     f"([{dist[1][0]:.2f}, {dist[1][1]:.2f}] holds every branch left)")
            if rate < CHECKED_RATE:
                note += (f"; caution: below {CHECKED_RATE / 1e3:g} kHz the best run may lie on "
                         "another branch (the held-out 10 kHz -21.25/2.6 before the size "
                         "sweep: a ball spacing off, in the interval: doc/methods/place_outer_branch.md)")
        elif calibrated and min(found)[0] / bins <= MAX_CHI2_PER_BIN:
            note += (f"; no distance from the load line either: every branch fits worse than "
                     f"the pit's own does in all but {REJECT_P:.0%} of records")
    else:
        # the best run's angle (to the search's step) and its branch's interval
        at = ordered[0][2]
        result.update(position_deg=at,
                      position_interval_deg=branch_interval(at, phase, (lo, hi), spacing),
                      branch_determined=True, best_run_size_deg=ordered[0][3],
                      chi2_margin=(ordered[1][0] - ordered[0][0]) if len(ordered) > 1 else None)
    result["note"] = note
    with open(os.path.join(a.out, "locate.json"), "w") as f:
        json.dump(result, f, indent=1)
        f.write("\n")
    if a.format == "json":
        print(json.dumps(result, indent=1))
    else:
        dist = result.get("distance_from_load_deg")
        pos = ("not determined" + ("" if dist is None else (
                   f"; {dist:.1f} deg from the load line either side "
                   f"[{result['distance_interval_deg'][0]:.1f}, "
                   f"{result['distance_interval_deg'][1]:.1f}]"))
               if not placed else
               f"{result['position_deg']:.1f} deg [{result['position_interval_deg'][0]:.1f}, "
               f"{result['position_interval_deg'][1]:.1f}] from the load direction")
        print(f"outer pit: {pos}\n  {note}")
        for c in result["candidates"]:
            print(f"  branch {c['branch_deg']:g} deg: best run {c['best_run_deg']:g} deg, "
                  f"{c['best_run_size_deg']:g} deg of pit, chi2 {c['chi2']:.0f} ({c['runs']} runs"
                  + ("" if c["p_value"] is None else f", p {c['p_value']:.2g}") + ")")


if __name__ == "__main__":
    main(sys.argv[1:])

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Folded pulses compared as the template fit compares them: a record's fold
(`diagnose --pulse-fold-out`: 'Y SE' per quarter sample, the entry at a quarter of the period)
against a run's, the load zone's first two harmonics removed (pulse_template.cpp's
without_cycle), aligned within two samples (sub-bin) and a constant fitted; chi2 in units of both
folds' standard errors (the averaged pulse's), over the fold or over the pulse's window alone
(pulse_window(): a straight line fitted there instead of the constant). And the search of the
runs of one place nearest a record, along the size and the angle. Used by
studies/branch_check.py (is the branch in the record?) and studies/locate_outer.py (the outer
pit's branch, the second stage after diagnose).
"""
import math

import numpy as np

OVERSAMPLE = 4  # fold bins per sample
EMPTY_FACTOR = 1e3  # an empty fold bin's error over the largest other's (diagnose's fold)
# the fit's allowance for two runs' differences (compare(model=True)): 2 % of the pulse, 5 us of
# timing per bin
MODEL_REL, MODEL_JITTER_S = 0.02, 5e-6
# the search's steps: sizes 8 % apart, angles 0.5 deg apart (within 3 deg of the start)
SIZE_STEP, ANGLE_STEP = 1.08, 0.5
# dense(): how far either side of a branch's refined best its runs are all looked at (deg)
DENSE_SPAN_DEG = 0.5
# the pulse's window in the fold, in periods (the entry at 0.25): from 0.1 before the entry to
# 0.25 after, or twice the ball's time over the pit when longer. Two realizations of one scene
# differ mostly outside it, in the load zone's slow cycle, which without_cycle's two harmonics
# (fitted on the fold's first 10 % and last 30 %) leave a few standard errors a bin apart: chi2
# up to 1402 over the whole fold of two 1.2 s realizations, 73 in the window with a line fitted
# (doc/report/sizing/template/scatter_*.md)
WINDOW_FROM, WINDOW_AFTER = 0.15, 0.25


def read_header(path):
    """The '# key: value' lines heading a fold or bank file, as a dict of strings."""
    head = {}
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            k, _, v = line[1:].partition(":")
            head[k.strip()] = v.strip()
    return head


def read_bank(path):
    """A template bank (studies/template_bank.py): ({(size, angle): (y, se)}, its bin in s)."""
    bank = {}
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                continue
            v = line.split()
            n = int(v[2])
            bank[(float(v[0]), float(v[1]))] = (np.array(v[3:3 + n], float),
                                                np.array(v[3 + n:3 + 2 * n], float))
    bin_s = read_header(path).get("bin (s)")
    return bank, None if bin_s is None else float(bin_s)


def read_fold(path, text=False):
    """A fold's 'Y SE' rows: numpy arrays, or with text=True the numbers as written."""
    y, se = [], []
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                a, b = line.split()
                y.append(a)
                se.append(b)
    return (y, se) if text else (np.array(y, float), np.array(se, float))


def without_cycle(y, se, harmonics=2, before=0.15):
    """pulse_template.cpp's without_cycle: the cycle's first harmonics fitted away from the
    pulse (from 0.45 of the period after the entry to `before` before it) and removed."""
    n = len(y)
    j = np.arange(n)
    u = j / n
    cols = [np.ones(n)]
    for h in range(1, harmonics + 1):
        cols += [np.cos(2 * math.pi * h * j / n), np.sin(2 * math.pi * h * j / n)]
    a = np.array(cols).T
    keep = ~((u >= 0.25 - before) & (u < 0.7))
    w = 1 / se[keep] ** 2
    coef = np.linalg.solve(a[keep].T @ (w[:, None] * a[keep]), a[keep].T @ (w * y[keep]))
    return y - a[:, 1:] @ coef[1:]


def empty_bins(se):
    """The bins no pass fell in (a period near a whole number of samples): diagnose's fold gives
    them EMPTY_FACTOR times the largest other bin's error (post/bearing/pulse_template.h,
    bins_without_passes: the same rule). A boolean mask."""
    top = float(np.max(se))
    high, low = se >= (1 - 1e-3) * top, se <= 2 * top / EMPTY_FACTOR
    return high if low.any() and bool(np.all(high | low)) else np.zeros(len(se), bool)


def shifted(y, base):
    """y read at j + base (linear interpolation, circular), for j = 0..len-1."""
    n = len(y)
    at = np.arange(n) + base
    fl = np.floor(at)
    u = at - fl
    i0 = fl.astype(int) % n
    return (1 - u) * y[i0] + u * y[(i0 + 1) % n], u


def pulse_window(size_deg, nb):
    """The pulse's window (fractions of the fold's period) for a pit of size_deg on a race of nb
    balls: a ball crosses it in size_deg nb / 360 of the outer race's ball-pass period."""
    crossing = size_deg * nb / 360.0
    return WINDOW_FROM, min(0.25 + max(WINDOW_AFTER, 2 * crossing), 0.9)


def misfit(rec, tmpl, n, shift, bin_s, model, scale_free, window=None, empty=None):
    """chi2 of rec (shifted) against tmpl over n bins, a constant (and with scale_free a scale
    of tmpl) fitted; with window (from, to: fractions of the period) over the bins there alone,
    a line fitted. empty: (rec's, tmpl's) empty_bins(), when the caller has them. Returns chi2,
    the residual, the weights (0 outside the window), the scale."""
    yr, u = shifted(rec[0], shift)
    ser, _ = shifted(rec[1], shift)
    yt, st = tmpl[0][:n], tmpl[1][:n]
    yr, ser = yr[:n], ser[:n]
    var = ser ** 2 + st ** 2
    if model:
        slope = 0.5 * (np.r_[yt[1:], yt[-1]] - np.r_[yt[0], yt[:-1]])
        var = var + (MODEL_REL * yt) ** 2 + (MODEL_JITTER_S / bin_s * slope) ** 2
    w = 1 / var
    a = np.ones((n, 1))
    if window:
        u = np.arange(n) / len(rec[0])
        w = np.where((u >= window[0]) & (u < window[1]), w, 0.0)
        a = np.c_[a, u - 0.5 * (window[0] + window[1])]
    # bins either fold has no pass in weigh nothing, and the chi2 is scaled to the bins compared:
    # a fold whose filled bins meet the other's empty ones would otherwise fit with no misfit
    # (diagnose's template fit read a 2.86 deg inner pit as 3.7 so), and one with half its bins
    # empty at half the chi2 of its rivals
    counted = int(np.count_nonzero(w))
    er, et = empty or (empty_bins(rec[1]), empty_bins(tmpl[1]))
    if er.any() or et.any():
        near = np.floor(np.arange(n) + shift + 0.5).astype(int) % len(rec[1])  # as shifted()
        w = np.where(er[near] | et[:n], 0.0, w)
    informative = int(np.count_nonzero(w))
    if scale_free:
        a = np.c_[a, yt]
    target = yr if scale_free else yr - yt
    if informative <= a.shape[1]:
        return math.inf, np.zeros(n), w, 1.0
    coef = np.linalg.solve(a.T @ (w[:, None] * a), a.T @ (w * target))
    r = target - a @ coef
    chi2 = float(np.sum(w * r * r)) * counted / informative
    return chi2, r, w, (coef[-1] if scale_free else 1.0)


def compared_bins(rec, tmpl, window=None):
    """How many bins compare() counts: 0.9 of the shorter fold, or those of them in the window."""
    n = int(0.9 * min(len(rec[0]), len(tmpl[0])))
    if not window:
        return n
    u = np.arange(n) / len(rec[0])
    return int(np.sum((u >= window[0]) & (u < window[1])))


def compare(rec, tmpl, bin_s, model=False, scale_free=False, window=None):
    """The least misfit over shifts within two samples (every bin, then the parabola); window:
    over the pulse's window alone (pulse_window())."""
    n = int(0.9 * min(len(rec[0]), len(tmpl[0])))
    reach = 2 * OVERSAMPLE
    empty = empty_bins(rec[1]), empty_bins(tmpl[1])  # once, for every shift
    c = [misfit(rec, tmpl, n, k, bin_s, model, scale_free, window, empty)[0]
         for k in range(-reach, reach + 1)]
    i = int(np.argmin(c))
    s = float(i - reach)
    if 0 < i < len(c) - 1 and math.isfinite(c[i - 1] + c[i + 1]):
        curv = c[i - 1] - 2 * c[i] + c[i + 1]
        if curv > 0:
            s2 = s + 0.5 * (c[i - 1] - c[i + 1]) / curv
            if misfit(rec, tmpl, n, s2, bin_s, model, scale_free, window, empty)[0] < c[i]:
                s = s2
    chi2, r, w, scale = misfit(rec, tmpl, n, s, bin_s, model, scale_free, window, empty)
    z = r * np.sqrt(w)
    k = int(np.argmax(np.abs(z)))
    return {"dprime": math.sqrt(chi2), "n": compared_bins(rec, tmpl, window),
            "max": float(abs(z[k])), "max_at_us": (k - len(rec[0]) / 4) * bin_s * 1e6,
            "shift_us": s * bin_s * 1e6, "scale": scale}


def chi2_noise(rec, tmpl, bin_s, window=None):
    """compare()'s chi2 (the standard errors alone)."""
    return compare(rec, tmpl, bin_s, window=window)["dprime"] ** 2


def log_vertex(sizes, chi2):
    """The least chi2 over log size: the parabola's vertex through the smallest and its two
    neighbours (kept between them), else the smallest point."""
    i = int(np.argmin(chi2))
    if i == 0 or i == len(chi2) - 1:
        return sizes[i], chi2[i]
    x = np.log(sizes[i - 1:i + 2])
    c = np.polyfit(x, chi2[i - 1:i + 2], 2)
    if c[0] <= 0:
        return sizes[i], chi2[i]
    v = min(max(-c[1] / (2 * c[0]), x[0]), x[2])
    return math.exp(v), max(float(np.polyval(c, v)), 0.0)


def prepared(fold):
    """A fold ready to compare: (y without the cycle, se)."""
    return without_cycle(*fold), fold[1]


def bank_best_size(bank, bin_s, rec, angle):
    """The bank's size (at its angle nearest `angle`) that fits the record best, between its
    sizes on the parabola."""
    sizes = sorted({k[0] for k in bank})
    near = min({k[1] for k in bank}, key=lambda a: abs(a - angle))
    c = [chi2_noise(rec, (without_cycle(*bank[(s, near)]), bank[(s, near)][1]), bin_s)
         for s in sizes]
    return log_vertex(sizes, c)[0]


def steps_to_least(f, limit):
    """f(k) at k = -1, 0, 1 steps along one coordinate, then on past the least end until the
    least lies between two (at most `limit` calls): the best k."""
    tried = {k: f(k) for k in (-1, 0, 1)}
    while True:
        order = sorted(tried)
        i = int(np.argmin([tried[k] for k in order]))
        if 0 < i < len(order) - 1 or len(tried) >= limit:
            return order[i]
        k = order[0] - 1 if i == 0 else order[-1] + 1
        tried[k] = f(k)


def search(chi2_at, start, sizes0, runs=None, angle_search=True):
    """The run of one place nearest a record: the least chi2, searched in turn along the size
    (runs SIZE_STEP apart) and the angle (ANGLE_STEP apart, within 3 deg) from `start` deg and each
    of sizes0 (the misfit has several minima in the size for long pits), then a run at the
    vertex of the parabola through the best size and its neighbours. chi2_at(angle, size): the
    chi2 of a run there against the record (angle to 0.01 deg, size to 0.001 deg). runs: (angle,
    size) -> chi2, filled. angle_search False: the size alone, at `start`. Returns (chi2, size,
    angle) of the best run. It may end in a local minimum of the angle and wander from `start`:
    scan() keeps to a window."""
    runs = {} if runs is None else runs

    def run(ang, sz):
        key = (round(ang, 2), round(sz, 3))
        if key not in runs:
            runs[key] = chi2_at(*key)
        return runs[key]

    def line(f, step_of, limit):
        return steps_to_least(lambda k: f(step_of(k)), limit)

    def descend(sz):
        ang = start
        for _ in range(3):
            k = line(lambda x: run(ang, x), lambda k: sz * SIZE_STEP ** k, 6)
            sz = round(sz * SIZE_STEP ** k, 3)
            if not angle_search:
                break
            ka = line(lambda x: run(x, sz), lambda k: ang + ANGLE_STEP * k, 13)
            if ka == 0:
                break
            ang = round(ang + ANGLE_STEP * ka, 2)
        line(lambda x: run(ang, x), lambda k: sz * SIZE_STEP ** k, 6)  # the size at the final angle
        sizes = sorted(x for (a_, x) in runs if a_ == round(ang, 2))
        v, _ = log_vertex(sizes, [runs[(round(ang, 2), x)] for x in sizes])
        run(ang, v)
        return min((runs[(round(ang, 2), x)], x, ang) for (a_, x) in runs if a_ == round(ang, 2))

    return min(descend(s) for s in sizes0)


def size_line(chi2_at, angle, size0, limit=12):
    """Runs at one angle, sizes SIZE_STEP apart from size0, until the least lies between two
    (at most `limit` runs: 0.46-2.2 times size0), then one at the parabola's vertex (log size):
    (chi2, size) of the best."""
    tried = {}

    def at(k):
        sz = round(size0 * SIZE_STEP ** k, 3)
        if sz not in tried:
            tried[sz] = chi2_at(angle, sz)
        return tried[sz]
    steps_to_least(at, limit)
    sizes = sorted(tried)
    v, _ = log_vertex(sizes, [tried[x] for x in sizes])
    v = round(v, 3)
    if v not in tried:
        tried[v] = chi2_at(angle, v)
    return min((c, sz) for sz, c in tried.items())


def angle_grid(lo, hi, step):
    """Angles `step` apart centred in [lo, hi] (to 0.01 deg), as scan() and rescan() sample."""
    n = max(int(math.floor((hi - lo) / step + 1e-9)), 0)
    mid = 0.5 * (lo + hi)
    return [round(mid + step * (k - n / 2), 2) for k in range(n + 1)]


def scan(chi2_at, lo, hi, sizes0, keep=2):
    """The run nearest a record within the window [lo, hi] deg (the misfit is rugged in the
    angle, with local minima ~1-2 deg apart, so it is sampled, not descended): every ANGLE_STEP
    at each of sizes0; at the `keep` best (angle, size) of those, with distinct angles, the size
    (size_line()); at the best of them the angle again ANGLE_STEP / 2 either side (kept within
    the window), at its size. chi2_at(angle, size) as search()'s. Returns (chi2, size, angle)
    of the best run."""
    angles = angle_grid(lo, hi, ANGLE_STEP)
    first = sorted((chi2_at(a, round(s, 3)), a, s) for s in sizes0 for a in angles)
    starts = []
    for _, a, s in first:
        if all(a != b for b, _ in starts):
            starts.append((a, s))
        if len(starts) == keep:
            break
    best = min(size_line(chi2_at, a, s) + (a,) for a, s in starts)
    c, sz, a = best
    for b in (a - ANGLE_STEP / 2, a + ANGLE_STEP / 2):
        if lo - 1e-9 <= b <= hi + 1e-9:
            best = min(best, (chi2_at(round(b, 2), sz), sz, round(b, 2)))
    return best


def refine(chi2_at, best, lo, hi, steps=(ANGLE_STEP / 4, ANGLE_STEP / 8)):
    """A window's best run (chi2, size, angle), from scan(), refined where the misfit's minimum is
    narrower than scan()'s grid (chi2 ~1 at the pit, hundreds 0.25-0.5 deg off): for each step in
    turn, the angle a step either side, going on the way it improves (within [lo, hi]), then the
    size at the new angle (size_line()). Angles to 0.001 deg. Returns (chi2, size, angle)."""
    for step in steps:
        at = best[2]
        for direction in (-1, 1):
            b = at
            while True:
                b = round(b + direction * step, 3)
                if not lo - 1e-9 <= b <= hi + 1e-9:
                    break
                c = chi2_at(b, best[1])
                if c >= best[0]:
                    break
                best = (c, best[1], b)
            if best[2] != at:
                break
        if best[2] != at:
            best = min(best, size_line(chi2_at, best[2], best[1]) + (best[2],))
    return best


def rescan(chi2_at, best, lo, hi, step=ANGLE_STEP / 2):
    """A branch's best run (chi2, size, angle) when scan() sampled the angles at a size off the
    pit's: there the misfit may hardly depend on the angle (a 0.7 deg pit sampled at 0.8 deg:
    chi2 200-300 over 3.5 deg, its own angle's neighbours not the lowest), and the angle scan()
    kept is chance. The angle again every `step` over [lo, hi] at the best size; from a better
    run, the size there (size_line()) and refine(). Returns (chi2, size, angle)."""
    sz = best[1]
    found = min((chi2_at(a, sz), sz, a) for a in angle_grid(lo, hi, step))
    if found >= best:
        return best
    found = min(found, size_line(chi2_at, found[2], sz) + (found[2],))
    return min(best, refine(chi2_at, found, lo, hi))


def sweep(chi2_at, best, lo, hi, size_lo, size_hi):
    """A branch's best run (chi2, size, angle) when it may have been searched from sizes far
    from the pit's: the misfit is rugged in the size too (the 10 kHz held-out -21.25/2.6 at
    -20.985 deg: chi2 982 at 2.39 deg of pit, 152 at 2.58, 2264 at 2.79), so size_line()'s
    walk from a start stops on the first least. The size every SIZE_STEP over [size_lo,
    size_hi] at the best angle; from a better run, refine() and dense(). Returns (chi2, size,
    angle)."""
    n = int(math.ceil(math.log(size_hi / size_lo) / math.log(SIZE_STEP) - 1e-9))
    sizes = [round(size_lo * SIZE_STEP ** k, 3) for k in range(n + 1)]
    found = min((chi2_at(best[2], sz), sz, best[2]) for sz in sizes)
    if found >= best:
        return best
    return min(best, dense(chi2_at, refine(chi2_at, found, lo, hi), lo, hi))


def dense(chi2_at, best, lo, hi, span=DENSE_SPAN_DEG, step=ANGLE_STEP / 8):
    """A refined best run (chi2, size, angle) checked against every run `step` apart within `span`
    deg either side at its size (within [lo, hi]): the misfit is rugged at 1/16 deg (each run its
    own realization), so refine()'s walk can stop on a local minimum up to ~60 above the branch's
    least (doc/ohmdem-post.md). When a run there fits better, the size again at its angle
    (size_line()). Returns (chi2, size, angle)."""
    at, sz = best[2], best[1]
    n = int(round(span / step))
    for k in range(-n, n + 1):
        b = round(at + k * step, 3)
        if k and lo - 1e-9 <= b <= hi + 1e-9:
            best = min(best, (chi2_at(b, sz), sz, b))
    if best[2] != at:
        best = min(best, size_line(chi2_at, best[2], sz) + (best[2],))
    return best

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The validation protocol: `ohmdem-post diagnose` on cases nobody chose.

N cases are drawn at random, with a seed, over the declared space SPACE below (bearing, defect
kind, size, place, load mode and load, speed, acquisition rate, noise). Each case is simulated
by the bearing deck (inputs/bearing_6208/in.bearing) for its sliding phase plus WINDOW s,
acquired as a user acquires a record (`ohmdem-post acquire`: the dry R through the deck's
0.1 A, an order-4 anti-alias filter at 0.4 x the rate, the drawn rate, white noise of the
drawn density, 16 bits on 0 to a range the record's level fits, the deck's shaft angle as a
third column, as a tachometer gives it), given the run's run.json beside the record with the
defect's kind, size and place removed (what a user's metadata holds), and diagnosed by the
frozen estimator `ohmdem-post diagnose --format json --column V RECORD` (ESTIMATOR_ARGS; its
version, binary and settings hashed into the report). The answers are scored against the
drawn truth: kind accuracy, race defects sized within 15 %, size intervals that cover the
truth, place error (radial load: inner from the shaft zero with the shaft angle, outer from
the load direction, modulo the ball spacing where the estimate says so), false alarms on the
healthy cases; per bearing, kind, load mode, rate and noise, with 95 % Wilson intervals.

  studies/protocol.py [--n N] [--seed S] [--quick] [--jobs J] [--report-only] OUT

--quick: the smoke version, 30 cases of seed QUICK_SEED (CI's validation tier). A case is
cached under OUT/cases/<key> by its parameters (key: a hash of them and of WINDOW): a rerun
skips the simulations and records it has (and the diagnoses made by the same estimator), so
the study resumes where it stopped and grows with N. The simulated 1 MHz signal is removed
once the record is acquired (--keep-signals keeps it).
Writes OUT/protocol.csv (one row per case) and OUT/protocol.md (the space, the estimator,
the tables). The study fails (exit 1) when a case cannot be run or diagnosed.
"""
import argparse
import concurrent.futures as cf
import datetime
import hashlib
import json
import math
import os
import shutil
import subprocess
import sys
import threading
import time

import common

# ---------------------------------------------------------------- the declared space
# Load: x the deck's default for the bearing (F_default = 320 N x (Nb Db^2) / (13 x 12.6 mm^2));
# speed: x the deck's default 500 rad/s. Noise densities: the detectability study's low and
# high electrical levels (10 nV/sqrt(Hz): a low-noise preamplifier; 1 uV/sqrt(Hz): a plain
# acquisition input, the level of a user's first record).
SPACE = {
    "bearing": ["machado2014", "6205-2RS_JEM", "6203-2RS_JEM", "6204_MOCHU"],
    "kind": ["inner", "outer", "ball", "none"],
    "size_deg": ("log-uniform", 0.2, 3.0),
    "position_deg": ("uniform", 0.0, 360.0),
    "load": ["force", "fixed", "radial"],
    "load_factor": ("log-uniform", 0.5, 3.0),
    "speed_factor": ("log-uniform", 0.5, 2.0),
    "rate_hz": [1e4, 2e4, 5e4],
    "noise": {"low": 1e-8, "high": 1e-6},
}
OMEGA_DEFAULT = 500.0          # rad/s, the deck's
WINDOW = 0.3                   # s analysed after the sliding phase
DEPTH = 5e-5                   # m, the pit depth of the sizing study (the pit's floor not reached
                               # below ~1.5 deg)
BITS = 16
REPORTED_SEED = 2026           # the seed of doc/report/protocol/protocol.md; tuned on: nothing
QUICK_SEED = 1                 # the smoke version's (and the script's own trial runs')
QUICK_N = 30
TRIAL_SEED = 7                 # the 2 cases that measured the cost per case
ESTIMATOR_ARGS = ["diagnose", "--format", "json", "--column", "V"]
# what a user's run.json does not hold: the defect's kind, size, place (and pit depth)
TRUTH_KEYS = ("defect", "size_deg", "size", "depth", "position", "position_deg", "dball",
              "dpocket", "dstart", "dwidth", "dtrack")
FAMILIES = ("inner", "outer", "ball", "cage")
SIZE_TOLERANCE = 0.15          # relative
PLACE_TOLERANCE = {"inner": 10.0, "outer": 15.0}  # deg
LOAD_DIRECTION = 90.0          # deg: the radial load's zone centre (+y) in the deck's frame
CURRENT = common.deck_defaults()["I"]  # A


def draw(seed, n):
    """The n cases of a seed: each a dict of the space's values (and its acquisition noise
    seed), drawn in a fixed order so that case i is the same for every n."""
    import numpy as np
    rng = np.random.default_rng(seed)

    def pick(spec):
        if isinstance(spec, dict):
            spec = list(spec)
        if isinstance(spec, list):
            return spec[int(rng.integers(len(spec)))]
        law, lo, hi = spec
        u = float(rng.random())
        return lo + u * (hi - lo) if law == "uniform" else math.exp(
            math.log(lo) + u * (math.log(hi) - math.log(lo)))

    cases = []
    for i in range(n):
        c = {k: pick(SPACE[k]) for k in ("bearing", "kind", "size_deg", "position_deg", "load",
                                         "load_factor", "speed_factor", "rate_hz", "noise")}
        c["noise_seed"] = int(rng.integers(1, 2 ** 31 - 1))
        if c["kind"] == "none":  # drawn all the same (the order of the draws kept), not used
            c["size_deg"] = c["position_deg"] = 0.0
        c["index"] = i
        cases.append(c)
    return cases


def rounded(c):
    """The case's values as the deck and the record get them (4 significant digits)."""
    return {k: (float(f"{v:.4g}") if isinstance(v, float) else v) for k, v in c.items()
            if k != "index"}


def key(c):
    text = json.dumps({**rounded(c), "window": WINDOW, "depth": DEPTH, "bits": BITS,
                       "range": "1-2-5 >= 1.1 peak"},
                      sort_keys=True)
    return hashlib.sha1(text.encode()).hexdigest()[:12]


def scene(c):
    """Deck variables of the case, and the expected sliding time (the deck's own rule,
    t_sliding_end, in.bearing) to size tend."""
    b = common.Bearing(c["bearing"])
    d = common.deck_defaults()
    f_default = 320 * (b.nb * b.db ** 2) / (13 * 0.0126 ** 2)
    r = rounded(c)
    omega = float(f"{OMEGA_DEFAULT * r['speed_factor']:.4g}")
    force = float(f"{f_default * r['load_factor']:.4g}")
    mu, rho = d.get("mu", 0.15), d.get("rho", 7800.0)
    scale = (rho * math.pi / 6 * b.db ** 3 * omega * b.dinn / 2 / (mu * force / b.nb)) / (
        7800 * math.pi / 6 * 0.0126 ** 3 * 500 * 0.048 / 2 / (0.15 * 320 / 13))
    tslide = 0.015 * scale
    v = {"bearing": c["bearing"], "omega": omega, "F": force, "load": c["load"],
         "defect": c["kind"], "tend": round(tslide + WINDOW + 0.002, 4),
         "restart_every": 0}
    if c["kind"] != "none":
        v.update({"size": r["size_deg"], "position": r["position_deg"], "depth": DEPTH})
    return v, omega, force


_print_lock = threading.Lock()
SIMULATED = []  # the seconds of each simulation this invocation ran


def say(text):
    with _print_lock:
        print(text, file=sys.stderr, flush=True)


def run_cmd(cmd, log):
    with open(log, "w") as f:
        return subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT).returncode


def nice_range(peak):
    """The ADC's upper bound a user picks for a signal: the 1-2-5 value at least 1.1 x its
    largest value (nothing clipped)."""
    e = math.floor(math.log10(1.1 * peak))
    for m in (1, 2, 5, 10):
        if m * 10 ** e >= 1.1 * peak:
            return m * 10 ** e
    return 10 ** (e + 1)


def simulate(folder, c):
    sim = os.path.join(folder, "sim")
    if common.finished(sim):
        return sim, None
    v, _, _ = scene(c)
    os.makedirs(sim, exist_ok=True)
    cmd = common.deck_command(common.BEARING_DECK, ["-var", "out", sim, "-log",
                              os.path.join(sim, "log.liggghts"), "-screen", "none"]
                              + common.variables(v))
    t0 = time.time()
    rc = run_cmd(cmd, os.path.join(sim, "stdout.txt"))
    if rc != 0 or not common.finished(sim):
        return None, f"simulation failed ({rc}): {' '.join(cmd)}; see {sim}/stdout.txt"
    with open(os.path.join(folder, "sim_seconds.txt"), "w") as f:
        f.write(f"{time.time() - t0:.2f}\n")
    SIMULATED.append(time.time() - t0)
    return sim, None


def make_record(folder, sim, c):
    """The record a user has: RECORD (time V angle_inner) and its run.json without the truth."""
    import numpy as np
    record = os.path.join(folder, "record.txt")
    meta_out = os.path.join(folder, "run.json")
    if os.path.exists(record) and os.path.exists(meta_out):
        return record, None
    with open(os.path.join(sim, "run.json")) as f:
        meta = json.load(f)
    t_from = float(meta["t_sliding_end"])
    signal = os.path.join(sim, "signal.txt")
    with open(signal) as f:
        names = f.readline().lstrip("#").split()
    a = np.loadtxt(signal, usecols=(names.index("time"), names.index("R"),
                                    names.index("angle_inner")))
    a = a[a[:, 0] >= t_from]
    finite = np.isfinite(a[:, 1])
    if not finite.any():
        return None, "the simulated R is infinite over the whole window (no ball in contact)"
    hi = nice_range(float(a[finite, 1].max()) * CURRENT)
    note = ""
    if not finite.all():
        # no ball in contact: an open circuit, which the instrument records as its over-range
        # (the current source at its compliance): R written at twice the ADC's top, clipped
        opened = os.path.join(sim, "signal_open_circuit.txt")
        r_open = np.where(finite, a[:, 1], 2 * hi / CURRENT)
        np.savetxt(opened, np.column_stack([a[:, 0], r_open]), header="time R", comments="# ",
                   fmt="%.17g")
        signal = opened
        note = (f"R infinite (no ball in contact) at {int((~finite).sum())} of {len(finite)} "
                "simulated samples: recorded as the instrument's over-range (clipped)")
    rate = c["rate_hz"]
    tmp = record + ".acq"
    args = ["acquire", "--column", "R", "--scale", repr(CURRENT), "--from", repr(t_from),
            "--lowpass", repr(0.4 * rate), "--order", "4", "--rate", repr(rate), "--bits",
            str(BITS), "--range", "0", repr(hi), "--noise-density",
            repr(SPACE["noise"][c["noise"]]), "--seed", str(c["noise_seed"]), "--name", "V",
            "--unit", "V", "--output", tmp, signal]
    r = subprocess.run([common.POST] + args, capture_output=True, text=True)
    if r.returncode != 0:
        return None, "acquire failed: " + r.stderr.strip()
    # the shaft angle at the record's times (the deck's angle_inner, interpolated: a
    # tachometer's angle)
    part = record + ".part"
    with open(tmp) as f, open(part, "w") as g:
        for line in f:
            if line.startswith("# time"):
                g.write("# time V angle_inner\n")
            elif line.startswith("#"):
                g.write(line)
            else:
                t, val = line.split()
                ang = float(np.interp(float(t), a[:, 0], a[:, 2]))
                g.write(f"{t} {val} {ang!r}\n")
    os.remove(tmp)
    user = {k: v for k, v in meta.items() if k not in TRUTH_KEYS}
    with open(meta_out + ".part", "w") as f:
        json.dump(user, f, indent=1)
    os.replace(meta_out + ".part", meta_out)
    # the record's header names the simulation's run.json: it gets the user's copy too (the
    # truth stays in case.json), so no reader of the header finds the defect
    shutil.copyfile(meta_out, os.path.join(sim, "run.json"))
    if note:
        with open(os.path.join(folder, "record_note.txt"), "w") as f:
            f.write(note + "\n")
    os.replace(part, record)
    if signal.endswith("signal_open_circuit.txt"):
        os.remove(signal)
    return record, None


def estimator():
    """The frozen estimator: its command, version and a hash of its binary and settings."""
    r = subprocess.run([common.POST, "--version"], capture_output=True, text=True)
    version = (r.stdout or r.stderr).strip().splitlines()[0] if (r.stdout or r.stderr) else "?"
    h = hashlib.sha256()
    with open(shutil.which(common.POST) or common.POST, "rb") as f:
        h.update(f.read())
    h.update(json.dumps(ESTIMATOR_ARGS).encode())
    return {"command": "ohmdem-post " + " ".join(ESTIMATOR_ARGS) + " RECORD",
            "version": version, "hash": h.hexdigest()[:16]}


def diagnose(folder, record, est):
    out = os.path.join(folder, f"diagnose_{est['hash']}.json")
    if os.path.exists(out):
        with open(out) as f:
            return json.load(f), None
    r = subprocess.run([common.POST] + ESTIMATOR_ARGS + [record], capture_output=True, text=True,
                       cwd=folder)
    if r.returncode != 0:
        return None, "diagnose failed: " + r.stderr.strip()
    try:
        d = json.loads(r.stdout)
    except ValueError as e:
        return None, f"diagnose printed no JSON: {e}"
    with open(out + ".part", "w") as f:
        json.dump(d, f)
    os.replace(out + ".part", out)
    return d, None


def wrap(x, period=360.0):
    return (x + period / 2) % period - period / 2


def score(c, d):
    """The case's row: the truth, the answer and their comparison."""
    v, omega, force = scene(c)
    kind = c["kind"]
    truth_diag = "none" if kind == "none" else kind
    defect = d.get("defect")
    size = d.get("size_deg")
    iv = d.get("size_interval_deg") or [None, None]
    row = {"case": c["index"], "key": key(c), "bearing": c["bearing"], "kind": kind,
           "size_deg": rounded(c)["size_deg"], "position_deg": rounded(c)["position_deg"],
           "load": c["load"], "load_factor": rounded(c)["load_factor"], "F_N": force,
           "speed_factor": rounded(c)["speed_factor"], "omega": omega, "rate_hz": c["rate_hz"],
           "noise": c["noise"], "noise_seed": c["noise_seed"], "diagnosis": defect,
           "score": d.get("score"), "kind_right": defect == truth_diag,
           "family_named": defect in FAMILIES, "detected": bool(d.get("detected")),
           "size_est_deg": size, "size_low_deg": iv[0], "size_high_deg": iv[1],
           "size_method": d.get("size_method"), "size_status": d.get("size_status"),
           "position_status": d.get("position_status"), "size_error_pct": None,
           "size_within": None,
           "size_covers": None, "position_est_deg": d.get("position_deg"),
           "position_reference": d.get("position_reference"),
           "position_modulo_deg": d.get("position_modulo_deg"), "position_error_deg": None,
           "place_within": None, "place_covers": None, "note": ""}
    if kind in ("inner", "outer"):
        s = row["size_deg"]
        sized = defect == kind and isinstance(size, (int, float))
        row["size_error_pct"] = 100 * (size / s - 1) if sized else None
        row["size_within"] = bool(sized and abs(size / s - 1) <= SIZE_TOLERANCE)
        row["size_covers"] = bool(sized and iv[0] is not None and iv[0] <= s and
                                  (iv[1] is None or s <= iv[1]))
        if c["load"] == "radial":
            truth = row["position_deg"] if kind == "inner" else row["position_deg"] - LOAD_DIRECTION
            pos, mod = row["position_est_deg"], row["position_modulo_deg"]
            ok_ref = row["position_reference"] == ("shaft zero" if kind == "inner"
                                                   else "load direction")
            if defect == kind and isinstance(pos, (int, float)) and ok_ref:
                period = mod if mod else 360.0
                err = wrap(pos - truth, period)
                row["position_error_deg"] = err
                row["place_within"] = abs(err) <= PLACE_TOLERANCE[kind]
                piv = d.get("position_interval_deg") or [None, None]
                if piv[0] is not None and piv[1] is not None:
                    lo, hi = wrap(piv[0] - truth, period), wrap(piv[1] - truth, period)
                    # the truth (0 after the shift) inside the arc from lo to hi
                    row["place_covers"] = (lo <= 0 <= hi) if lo <= hi else (lo <= 0 or 0 <= hi)
                else:
                    row["place_covers"] = False
            else:
                row["place_within"] = row["place_covers"] = False
    return row


def one(out, c, est, keep):
    folder = os.path.join(out, "cases", key(c))
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "case.json"), "w") as f:
        json.dump({**rounded(c), "window": WINDOW, "depth": DEPTH}, f, indent=1)
    record = os.path.join(folder, "record.txt")
    if not (os.path.exists(record) and os.path.exists(os.path.join(folder, "run.json"))):
        sim, err = simulate(folder, c)
        if err:
            return None, err
        record, err = make_record(folder, sim, c)
        if err:
            return None, err
        if not keep:
            for name in ("signal.txt", "signal.npy"):
                p = os.path.join(sim, name)
                if os.path.exists(p):
                    os.remove(p)
    d, err = diagnose(folder, record, est)
    if err:
        return None, err
    row = score(c, d)
    note = os.path.join(folder, "record_note.txt")
    if os.path.exists(note):
        row["note"] = open(note).read().strip()
    return row, None


# ---------------------------------------------------------------- the tables
def wilson(k, n):
    from scipy.stats import binomtest
    if n == 0:
        return None
    ci = binomtest(k, n).proportion_ci(confidence_level=0.95, method="wilson")
    return ci.low, ci.high


def rate_text(k, n):
    if n == 0:
        return "-"
    lo, hi = wilson(k, n)
    return f"{k}/{n} ({100 * k / n:.0f} % [{100 * lo:.0f}, {100 * hi:.0f}])"


METRICS = [
    ("kind right", lambda r: True, "kind_right"),
    ("race sized within 15 %", lambda r: r["kind"] in ("inner", "outer"), "size_within"),
    ("size interval covers", lambda r: r["kind"] in ("inner", "outer"), "size_covers"),
    ("place within 10/15 deg (radial)", lambda r: r["place_within"] is not None, "place_within"),
    ("place interval covers (radial)", lambda r: r["place_covers"] is not None, "place_covers"),
    ("healthy: family named", lambda r: r["kind"] == "none", "family_named"),
    ("healthy: detected", lambda r: r["kind"] == "none", "detected"),
]


def table(rows, by, title):
    groups = {}
    for r in rows:
        groups.setdefault(r[by] if by else "all", []).append(r)
    lines = [f"### {title}", "", f"| {by or 'cases'} | n | " +
             " | ".join(m[0] for m in METRICS) + " |", "|---" * (len(METRICS) + 2) + "|"]
    for g in sorted(groups, key=str):
        rs = groups[g]
        cells = []
        for _, where, col in METRICS:
            sel = [r for r in rs if where(r)]
            cells.append(rate_text(sum(bool(r[col]) for r in sel), len(sel)))
        label = f"{g:g} Hz" if isinstance(g, float) else str(g)
        lines.append(f"| {label} | {len(rs)} | " + " | ".join(cells) + " |")
    return lines + [""]


def errors_table(rows):
    """The size and place errors of the race defects identified, per kind and load."""
    lines = ["### Errors of the race defects named right", "",
             "| kind | load | named | sized | median abs size error | 90th pct | place given | "
             "median abs place error (deg) |", "|---" * 8 + "|"]
    for kind in ("inner", "outer"):
        for load in SPACE["load"]:
            rs = [r for r in rows if r["kind"] == kind and r["load"] == load]
            named = [r for r in rs if r["kind_right"]]
            errs = sorted(abs(r["size_error_pct"]) for r in named if r["size_error_pct"] is not None)
            perr = sorted(abs(r["position_error_deg"]) for r in named
                          if r["position_error_deg"] is not None)
            pct = lambda e, q: f"{e[min(len(e) - 1, int(q * len(e)))]:.0f} %" if e else "-"
            lines.append(f"| {kind} | {load} | {len(named)}/{len(rs)} | {len(errs)} | "
                         f"{pct(errs, 0.5)} | {pct(errs, 0.9)} | {len(perr)} | "
                         + (f"{perr[len(perr) // 2]:.1f}" if perr else "-") + " |")
    return lines + [""]


def confusion(rows):
    answers = sorted({r["diagnosis"] for r in rows}, key=str)
    lines = ["### Confusion (truth down, answer across)", "",
             "| truth | " + " | ".join(answers) + " |", "|---" * (len(answers) + 1) + "|"]
    for kind in SPACE["kind"]:
        rs = [r for r in rows if r["kind"] == kind]
        lines.append(f"| {kind} | " + " | ".join(
            str(sum(r["diagnosis"] == a for r in rs)) for a in answers) + " |")
    return lines + [""]


def space_text():
    lines = ["| parameter | drawn from |", "|---|---|"]
    for k, v in SPACE.items():
        if isinstance(v, dict):
            text = ", ".join(f"{n} ({d:g} V/sqrt(Hz))" for n, d in v.items()) + ", uniform"
        elif isinstance(v, list):
            text = ", ".join(f"{x:g}" if isinstance(x, float) else str(x) for x in v) + ", uniform"
        else:
            text = f"{v[0]} on [{v[1]:g}, {v[2]:g}]"
        lines.append(f"| {k} | {text} |")
    return lines


def write_report(out, rows, args, est, cost):
    common.write_csv(os.path.join(out, "protocol.csv"), rows, quoted=("size_method", "note"))
    cmd = "studies/protocol.py " + ("--quick " if args.quick else
                                    f"--n {args.n} --seed {args.seed} ") + "OUT"
    lines = ["# The validation protocol: diagnose on cases drawn at random", "",
             f"Regenerated at commit {common.source_commit()}, "
             f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC, by `{cmd}`. "
             f"{len(rows)} cases, seed {args.seed}.", "",
             f"Estimator (frozen): `{est['command']}`, {est['version']}, hash {est['hash']} "
             "(sha256 of the binary and its settings). The record's run.json lies beside it, "
             "without the defect's kind, size and place; the estimator reads bearing, speed, "
             "load and sliding time from it.", "",
             "## The space", ""] + space_text() + [
             "",
             f"Load: x the deck's default for the bearing (320 N x Nb Db^2 / (13 x (12.6 mm)^2)); "
             f"speed: x {OMEGA_DEFAULT:g} rad/s. Pits {DEPTH * 1e6:g} um deep; each run simulated "
             f"for its sliding phase (the deck's t_sliding_end) plus {WINDOW:g} s at 1 MHz. "
             f"Record: R x {CURRENT:g} A, order-4 Butterworth at 0.4 x the rate, white noise of "
             f"the drawn density (its own seed per case), {BITS} bits on 0 to the 1-2-5 value "
             "at least 1.1 x the record's largest value (nothing clipped), the deck's shaft angle as a column "
             "(`angle_inner`). Place: radial load only (under force and fixed loads the "
             "estimator says it is not determined, rightly), inner from the shaft zero (within "
             f"{PLACE_TOLERANCE['inner']:g} deg), outer from the load direction (within "
             f"{PLACE_TOLERANCE['outer']:g} deg, modulo the ball spacing when the estimate "
             "gives one). A race defect not named right counts as not sized and not placed. "
             "Intervals: 95 % Wilson (scipy.stats.binomtest).", "",
             f"Seeds: {args.seed} reported. Tuned on: nothing (the estimator is frozen). The "
             f"script itself (its chain's ADC range rule, its scoring) was tried on seed "
             f"{QUICK_SEED} (the smoke version's 30 cases) and seed {TRIAL_SEED} (2 cases, the "
             "cost per case); seeds 3, 11 and 12 draw cases for the tests of the draw, without "
             "a run.", "",
             "Cost: " + cost, "",
             f"Open circuits: {sum(bool(r['note']) for r in rows)} case(s) lost every ball's "
             "contact for part of the window (R infinite in the simulation: light loads at high "
             "speeds); their record holds the instrument's over-range there, clipped (the `note` "
             "column of protocol.csv). They are scored as the others.", "", "## Results", ""]
    lines += table(rows, None, "All cases")
    for by, title in (("kind", "Per defect kind"), ("bearing", "Per bearing"),
                      ("load", "Per load mode"), ("rate_hz", "Per acquisition rate"),
                      ("noise", "Per noise level")):
        lines += table(rows, by, title)
    lines += errors_table(rows) + confusion(rows)
    low20 = [r for r in rows if r["rate_hz"] == 2e4 and r["noise"] == "low"]
    lines += table(low20, "kind", "The goal's setting: 20 kHz, low noise, per kind")
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "protocol.md"), "w") as f:
        f.write(text)
    print(text)


def read_rows(path):
    import csv
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            for k in ("kind_right", "family_named", "detected", "size_within", "size_covers",
                      "place_within", "place_covers"):
                r[k] = None if r[k] == "" else r[k] == "True"
            for k in ("rate_hz", "size_error_pct", "position_error_deg"):
                r[k] = float(r[k]) if r[k] else None
            rows.append(r)
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out", help="output folder (its cases/ is the cache)")
    p.add_argument("--n", type=int, default=200, help="cases [200]")
    p.add_argument("--seed", type=int, default=REPORTED_SEED, help=f"[{REPORTED_SEED}]")
    p.add_argument("--quick", action="store_true",
                   help=f"the smoke version: {QUICK_N} cases of seed {QUICK_SEED}")
    p.add_argument("--jobs", type=int, default=2, help="cases in parallel [2]")
    p.add_argument("--keep-signals", action="store_true", help="keep the 1 MHz signal.txt")
    p.add_argument("--report-only", action="store_true",
                   help="rewrite protocol.md from OUT/protocol.csv")
    a = p.parse_args()
    if a.n < 1 or a.jobs < 1:
        sys.exit("protocol: --n and --jobs expect a whole number >= 1")
    if a.quick:
        a.n, a.seed = QUICK_N, QUICK_SEED
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    est = estimator()
    if a.report_only:
        rows = read_rows(os.path.join(out, "protocol.csv"))
        write_report(out, rows, a, est, "(report rewritten from protocol.csv)")
        return
    cases = draw(a.seed, a.n)
    t0, done, failures, rows = time.time(), [0], [], [None] * len(cases)
    lock = threading.Lock()

    def task(c):
        r, err = one(out, c, est, a.keep_signals)
        with lock:
            done[0] += 1
            left = (time.time() - t0) / done[0] * (len(cases) - done[0]) / 60
            say(f"protocol: {done[0]}/{len(cases)} case {c['index']} {c['bearing']} {c['kind']} "
                f"{c['load']} {c['rate_hz']:g} Hz: " + (err if err else r["diagnosis"])
                + f" (~{left:.0f} min left)")
            if err:
                failures.append(f"case {c['index']} ({key(c)}): {err}")
            else:
                rows[c["index"]] = r

    with cf.ThreadPoolExecutor(a.jobs) as ex:
        list(ex.map(task, cases))
    timed = []
    for c in cases:
        f = os.path.join(out, "cases", key(c), "sim_seconds.txt")
        if os.path.exists(f):
            with open(f) as g:
                timed.append(float(g.read()))
    cost = ((f"{sum(timed) / len(timed):.1f} s wall per simulation on average ({len(timed)} "
             "timed when they ran, --jobs on a shared 2-core machine); " if timed else "")
            + f"this invocation: {len(SIMULATED)} simulated, {len(cases) - len(SIMULATED)} from "
            f"the cache, {(time.time() - t0) / 60:.1f} min wall with --jobs {a.jobs}.")
    if failures:
        sys.exit("protocol: failed cases:\n  " + "\n  ".join(failures))
    write_report(out, [r for r in rows if r], a, est, cost)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The load and speed study the paper announced (Machado et al. 2014, conclusion): statistical
indicators of R(t) (RMS, kurtosis, crest, peak) and the diagnosis against the load F and the
inner ring speed, healthy and with a 1 deg inner-race defect, outer ring under force control
(the paper's) and held (fixed).
  studies/load_speed.py [--quick] [--jobs N] [--report-only] OUT
Writes into OUT:
  load_speed.csv   one row per run (operating point, load mode, defect, indicators, diagnosis,
                   healthy R against the closed form of equal load sharing)
  load_speed.md    the tables, the inner-contact speed limit, the figures and what they show
  *.png            indicators against F and against omega
"""
import argparse
import concurrent.futures as cf
import json
import math
import os
import subprocess
import sys

import common

# The bearing from its catalog file (inputs/bearings/machado2014: Table 1 of the paper) and the deck's
# material defaults (in.bearing).
BEARING = common.Bearing("machado2014")
NB, DB, DEXT, DINN = BEARING.nb, BEARING.db, BEARING.dext, BEARING.dinn
RC_INN, RC_EXT = BEARING.rcinn, BEARING.rcext
_DECK = common.deck_defaults()
E, NU, RHO, GAMMA = _DECK["E"], _DECK["nu"], _DECK["rho"], _DECK["gamma"]
DP = (DEXT + DINN) / 2
RP = DP / 2
RB = DB / 2
MBALL = RHO * 4 / 3 * math.pi * RB ** 3


def cage_speed(omega):
    """Orbital speed of the balls for a fixed outer ring (rad/s): omega/2 (1 - d/D)."""
    return omega / 2 * (1 - DB / DP)


def centrifugal(omega):
    """Centrifugal force on one ball orbiting at the cage speed (N)."""
    return MBALL * cage_speed(omega) ** 2 * RP


def omega_limit(force):
    """Inner speed at which the inner contacts unload: m w_c^2 r_p = F / Nb (isotropic load)."""
    return 2 / (1 - DB / DP) * math.sqrt(force / NB / (MBALL * RP))


# Exact Hertz constants of the ball-race contacts (doc/fix_bearing_race.md), N/m^1.5.
K_INNER, K_OUTER = 3.10e10, 2.94e10
MRING = 0.15  # outer ring mass of the deck (kg)


def ring_period(force, omega):
    """Period of the force-controlled ring on its Nb ball contacts (s): each ball is an inner and
    an outer Hertz contact in series, stiffness dQ/d(delta) = 1.5 K delta^0.5 at its load."""
    def k(q, kh):
        return 1.5 * kh * (q / kh) ** (1 / 3)
    q_out = force / NB
    q_in = q_out - centrifugal(omega)
    k_ball = 1 / (1 / k(q_in, K_INNER) + 1 / k(q_out, K_OUTER))
    return 2 * math.pi * math.sqrt(MRING / (NB * k_ball))


def greenwood_area(q, a, b):
    """Greenwood's contact area (m^2) for load q and curvature sums a, b (1/m); doc/methods/hertz_contact.md."""
    e_eff = E / (2 * (1 - NU ** 2))
    r_eff = (a * b * (a + b) / 2) ** (-1 / 3)
    c = (3 * q * r_eff / (4 * e_eff)) ** (1 / 3)
    return math.pi * c * c


def closed_form_r(force, omega):
    """R of Nb equal balls (paper eq. 1, Greenwood areas): each ball one resistor between its
    outer contact (load F/Nb) and its inner contact (F/Nb minus the centrifugal force), the
    two points diametrically opposite (1 - cos theta = 2): R_ball = 4 V / (gamma S_i S_o)."""
    q_out = force / NB
    q_in = q_out - centrifugal(omega)
    if q_in <= 0:
        return math.inf
    s_in = greenwood_area(q_in, 1 / RB + 2 / DINN, 1 / RB - 1 / RC_INN)
    s_out = greenwood_area(q_out, 1 / RB - 2 / DEXT, 1 / RB - 1 / RC_EXT)
    v = 4 / 3 * math.pi * RB ** 3
    return 4 * v / (GAMMA * s_in * s_out) / NB


def simulate(out, name, tend, variables):
    folder = os.path.join(out, name)
    os.makedirs(folder, exist_ok=True)
    cmd = common.deck_command(common.BEARING_DECK, [
        "-var", "out", folder, "-var", "tend", repr(tend), "-log",
        os.path.join(folder, "log.liggghts"), "-screen", "none"] + common.variables(variables))
    common.run(cmd, os.path.join(folder, "stdout.txt"), who="load_speed")
    return folder


def sweep_point(out, tag, tend, variables):
    """The four runs of an operating point (ring force/fixed x healthy/inner) as a case table
    (doc/case_table.md) through in.sweep, in turn; the point's values are common to the four.
    A rerun skips the runs finished with the same parameters. {(load, defect): folder}."""
    root = os.path.join(out, tag)
    os.makedirs(root, exist_ok=True)
    table = os.path.join(root, "cases.csv")
    pairs = [(load, defect) for load in ("force", "fixed") for defect in ("none", "inner")]
    common.case_table(table, ["load", "defect"], pairs)
    cmd = common.sweep_command(root, table, {"tend": repr(tend), **variables},
                               os.path.join(root, "log.sweep"))
    common.run(cmd, os.path.join(root, "stdout.txt"), who="load_speed", cwd=root)
    return {(l, d): os.path.join(root, f"load_{l}_defect_{d}") for l, d in pairs}


def sliding_end(folder, omega):
    """First time after which the balls orbit at the kinematic cage speed within 1e-3."""
    path = os.path.join(folder, "signal.txt")
    names = open(path).readline().lstrip("#").split()
    it, iw = names.index("time"), names.index("omega_balls")
    target, last_bad = cage_speed(omega), 0.0
    with open(path) as f:
        next(f)
        for line in f:
            v = line.split()
            if abs(float(v[iw]) / target - 1) > 1e-3:
                last_bad = float(v[it])
    return last_bad


def masked_duty(path, t_from):
    """Fraction of the window during which a contact is masked by the defect (n_masked > 0)."""
    names = open(path).readline().lstrip("#").split()
    it, im = names.index("time"), names.index("n_masked")
    n = hits = 0
    with open(path) as f:
        next(f)
        for line in f:
            v = line.split()
            if float(v[it]) >= t_from:
                n += 1
                hits += float(v[im]) > 0
    return hits / n


def rectangle_kurtosis(d):
    """Kurtosis of an ideal rectangle train occupying a fraction d of the time (doc/report)."""
    return (1 - 3 * d * (1 - d)) / (d * (1 - d)) if 0 < d < 1 else float("nan")


# Below this relative fluctuation the healthy R is constant to round-off: its kurtosis and
# crest describe rounding noise, not the bearing.
ROUND_OFF = 1e-9


def post_json(args):
    return json.loads(common.post(args + ["--format", "json"], who="load_speed").stdout)


def operating_points(quick):
    forces = [150, 320, 1000, 3000] if quick else [150, 250, 320, 500, 1000, 2000, 3000]
    omegas = [100, 250, 500, 750] if quick else [100, 200, 300, 400, 500, 600, 750]
    points = [(f, 500.0) for f in forces] + [(320.0, w) for w in omegas if w != 500]
    return sorted(set((float(f), float(w)) for f, w in points))


def study_point(out, force, omega, revolutions):
    """Pilot run (sliding phase), then force/fixed x healthy/inner with the defect appearing
    after the sliding phase (the held ring is held at the healthy rolling radius)."""
    tag = f"F{force:g}_w{omega:g}"
    pilot = simulate(out, f"pilot_{tag}", 0.06, {"F": force, "omega": omega, "nout": 10})
    t_slide = sliding_end(pilot, omega)
    t_settle = t_slide + 0.002
    t_from = t_settle + 0.002
    window = revolutions * 2 * math.pi / omega
    folders = sweep_point(out, tag, t_from + window,
                          {"F": force, "omega": omega, "size": 1.0, "tsettle": t_settle,
                           "dstart": t_settle, "tslide": t_from})
    rows = []
    for load in ("force", "fixed"):
        for defect in ("none", "inner"):
            folder = folders[(load, defect)]
            sig = os.path.join(folder, "signal.txt")
            st = post_json(["stats", "--from", repr(t_from), sig])
            st_ac = post_json(["stats", "--remove-mean", "--from", repr(t_from), sig])
            dg = post_json(["diagnose", "--from", repr(t_from), sig])
            duty = masked_duty(sig, t_from)
            rows.append({
                "F_N": force, "omega_rad_s": omega, "load": load, "defect": defect,
                "t_sliding_end_s": t_slide, "window_s": window,
                "mean_ohm": st["mean"], "rms_ohm": st["rms"], "peak_ohm": st["peak"],
                "crest": st["crest"], "kurtosis": st["kurtosis"], "std_ohm": st["std"],
                "crest_ac": st_ac["crest"], "std_rel": st["std"] / st["mean"],
                "duty": duty, "kurtosis_rectangle": rectangle_kurtosis(duty),
                "diagnosis": dg["defect"], "score": dg["score"],
                "detected": dg.get("detected", dg["defect"] != "none"),
                "frequency_hz": dg.get("frequency_hz") or 0.0,
                "bpfi_hz": NB * omega / (2 * math.pi) / 2 * (1 + DB / DP),
                "r_closed_form_ohm": closed_form_r(force, omega),
            })
    return rows


def fmt(v):
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        return f"{v:.9g}"
    return str(v)


def read_csv(path):
    def value(v):
        if v in ("yes", "no"):
            return v == "yes"
        try:
            return float(v)
        except ValueError:
            return v
    with open(path) as f:
        cols = f.readline().strip().split(",")
        return [dict(zip(cols, map(value, line.strip().split(",")))) for line in f if line.strip()]


def write_outputs(out, rows, quick):
    cols = list(rows[0].keys())
    with open(os.path.join(out, "load_speed.csv"), "w") as f:
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join(fmt(r[c]) for c in cols) + "\n")
    for sweep, x, fixed in (("F", "F_N", "omega_rad_s=500"), ("omega", "omega_rad_s", "F_N=320")):
        for load in ("force", "fixed"):
            for ys, what in (("kurtosis", "kurtosis"), ("crest_ac,score", "crest (mean removed), score"),
                             ("rms_ohm,peak_ohm", "RMS, peak")):
                png = os.path.join(out, f"{sweep}_{load}_{ys.split(',')[0]}.png")
                subprocess.run([common.POST, "plot", "--kind", "indicators", "--x", x, "--y", ys,
                                "--where", f"{fixed},load={load},defect=inner",
                                "--title", f"1 deg inner defect, ring {load}: {what} vs {x}",
                                "--output", png, os.path.join(out, "load_speed.csv")], check=True)
    w_lim = {f: omega_limit(f) for f in sorted({r["F_N"] for r in rows})}
    lines = ["# Load and speed study, machado2014 (the paper's model of an SKF 6208) (ohmdem)", "",
             f"Regenerated at {common.made_at()} by `studies/load_speed.py {'--quick ' if quick else ''}OUT`. "
             "Indicators of R over a window of whole shaft revolutions after the sliding phase "
             "(found per operating point from a pilot run: the balls orbit at the kinematic cage "
             "speed within 1e-3); the defect (1 deg, inner race) appears 2 ms after that, the held "
             "ring is held from then on, the window starts 2 ms later.", "",
             "## Where the balls keep the inner contact", "",
             "Under the isotropic load F each ball carries F/Nb on the outer race and F/Nb - m w_c^2 r_p "
             "on the inner race (w_c = w/2 (1 - d/D), the cage speed). The inner contacts unload at "
             "w_max = 2/(1 - d/D) sqrt(F / (Nb m r_p)), with m = "
             f"{MBALL * 1e3:.3f} g (rho 7800), r_p = {RP * 1e3:.2f} mm:", "",
             "| F (N) | w_max (rad/s) | at 500 rad/s: inner load / outer load |", "|---|---|---|"]
    for f, wl in w_lim.items():
        lines.append(f"| {f:g} | {wl:.0f} | {1 - centrifugal(500) / (f / NB):.3f} |")
    lines += ["", "All points of the study lie below w_max of their load; the lowest load at 500 rad/s "
              f"that keeps the inner contact is F = {NB * centrifugal(500):.0f} N.", "",
              "## Healthy R against the closed form (equal load sharing, eq. 1, Greenwood)", "",
              "| F (N) | w (rad/s) | R sim, force (ohm) | R closed form (ohm) | relative difference |",
              "|---|---|---|---|---|"]
    for r in rows:
        if r["load"] == "force" and r["defect"] == "none":
            d = r["mean_ohm"] / r["r_closed_form_ohm"] - 1
            lines.append(f"| {r['F_N']:g} | {r['omega_rad_s']:g} | {r['mean_ohm']:.6f} | "
                         f"{r['r_closed_form_ohm']:.6f} | {d:+.2e} |")
    lines += ["", "## Indicators and diagnosis", "",
              "Kurtosis and crest (AC: mean removed) of a healthy R whose relative standard deviation "
              f"is below {ROUND_OFF:g} are shown as `round-off`: R is then constant to the last digits "
              "and those moments describe rounding, not the bearing. Duty: fraction of the window "
              "with a masked contact; rectangle: the kurtosis (1 - 3d(1-d))/(d(1-d)) of an ideal "
              "rectangle train of that duty.", "",
              "| F (N) | w (rad/s) | ring | defect | mean (ohm) | std/mean | peak/mean | crest (AC) | "
              "kurtosis | duty | rectangle | diagnosis | score | detected |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        flat = r["std_rel"] < ROUND_OFF
        kurt = "round-off" if flat else f"{r['kurtosis']:.3g}"
        crest = "round-off" if flat else f"{r['crest_ac']:.3f}"
        duty = f"{r['duty']:.4f}" if r["duty"] > 0 else "-"
        rect = f"{r['kurtosis_rectangle']:.1f}" if r["duty"] > 0 else "-"
        lines.append(f"| {r['F_N']:g} | {r['omega_rad_s']:g} | {r['load']} | {r['defect']} | "
                     f"{r['mean_ohm']:.5f} | {r['std_rel']:.2e} | {r['peak_ohm'] / r['mean_ohm']:.4f} | "
                     f"{crest} | {kurt} | {duty} | {rect} | {r['diagnosis']} | "
                     f"{r['score']:.2f} | {fmt(r['detected'])} |")
    inner = [r for r in rows if r["defect"] == "inner"]
    ident = sum(r["diagnosis"] == "inner" for r in inner)
    healthy = [r for r in rows if r["defect"] == "none" and r["load"] == "force"]
    worst = max(healthy, key=lambda r: abs(r["mean_ohm"] / r["r_closed_form_ohm"] - 1))

    def span(load, key):
        v = [float(r[key]) for r in inner if r["load"] == load]
        return f"{min(v):.3g}" if f"{min(v):.3g}" == f"{max(v):.3g}" else f"{min(v):.3g} to {max(v):.3g}"

    def at(load, key, **where):
        return [r[key] for r in inner if r["load"] == load
                and all(r[k] == v for k, v in where.items())][0]

    def healthy_mean(r):
        return [h["mean_ohm"] for h in rows if h["defect"] == "none" and h["load"] == r["load"]
                and h["F_N"] == r["F_N"] and h["omega_rad_s"] == r["omega_rad_s"]][0]

    jumps = [r["peak_ohm"] / healthy_mean(r) for r in inner]
    w_lo = min(r["omega_rad_s"] for r in inner)
    w_hi = max(r["omega_rad_s"] for r in inner)

    def passage_ms(w):  # 1 deg crossed at the speed of the inner ring relative to the cage
        return math.radians(1.0) / (w - cage_speed(w)) * 1e3

    lines += ["", "## What the study shows", "",
              f"- Healthy R follows the closed form of equal load sharing at every operating point "
              f"(largest difference {abs(worst['mean_ohm'] / worst['r_closed_form_ohm'] - 1):.1e}, at "
              f"F = {worst['F_N']:g} N, w = {worst['omega_rad_s']:g} rad/s, where the inner contacts "
              "carry the least load); it falls as F^(-4/3) with the load and rises with the speed as "
              "the centrifugal force unloads the inner contacts.",
              f"- The 1 deg inner defect is identified as inner in {ident} of {len(inner)} runs "
              f"(scores {span('force', 'score')} under force, {span('fixed', 'score')} held): on the "
              "noiseless signal, load and speed do not limit identification; the instrument does "
              "(see the detectability study).",
              f"- The break itself raises R to R0·Nb/(Nb-1) = {NB / (NB - 1):.4f} R0 at every point "
              f"(defective peak over healthy mean: {min(jumps):.4f} to {max(jumps):.4f}).",
              f"- Ring held: the kurtosis ({span('fixed', 'kurtosis')}) and the AC crest "
              f"({span('fixed', 'crest_ac')}) do not depend on load or speed: R is a rectangle train whose "
              f"duty (the defect's angular share, {span('fixed', 'duty')}) fixes the kurtosis at the "
              f"rectangle law ({span('fixed', 'kurtosis_rectangle')}).",
              f"- Ring under force (the paper's load): kurtosis {span('force', 'kurtosis')}, highest at "
              f"the lowest speed ({at('force', 'kurtosis', F_N=320.0, omega_rad_s=w_lo):.3g} at {w_lo:g} "
              f"rad/s against {at('force', 'kurtosis', F_N=320.0, omega_rad_s=w_hi):.3g} at {w_hi:g}). "
              "The ring tightens on the remaining balls on its own time scale (its period on the ball "
              f"contacts, {ring_period(320.0, w_lo) * 1e3:.2f} ms at 320 N and {w_lo:g} rad/s, "
              f"{ring_period(320.0, w_hi) * 1e3:.2f} ms at {w_hi:g}): a passage lasting "
              f"{passage_ms(w_lo):.2f} ms ({w_lo:g} rad/s) holds a whole swing, R rises by 1/(Nb-1) and "
              f"then falls below R0 before the ball leaves the zone; at {w_hi:g} rad/s "
              f"({passage_ms(w_hi):.3f} ms) the pulse ends before the ring has moved much. The indicators "
              "of a force-controlled ring therefore depend on speed, those of a held ring do not: a "
              "kurtosis threshold learnt at one speed does not transfer to another.", ""]
    for sweep in ("F", "omega"):
        for load in ("force", "fixed"):
            lines += [f"![{sweep}, {load}]({sweep}_{load}_kurtosis.png) "
                      f"![{sweep}, {load}]({sweep}_{load}_crest_ac.png) "
                      f"![{sweep}, {load}]({sweep}_{load}_rms_ohm.png)", ""]
    open(os.path.join(out, "load_speed.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out", help="output folder")
    p.add_argument("--quick", action="store_true", help="reduced grid (a few minutes)")
    p.add_argument("--jobs", type=int, default=2, help="runs in parallel [2]")
    p.add_argument("--report-only", action="store_true",
                   help="rewrite the report and figures from OUT/load_speed.csv, no runs")
    a = p.parse_args()
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    if a.report_only:
        write_outputs(out, read_csv(os.path.join(out, "load_speed.csv")), a.quick)
        return
    points = operating_points(a.quick)
    for f, w in points:
        if w >= omega_limit(f):
            sys.exit(f"load_speed: omega {w} is beyond the inner-contact limit {omega_limit(f):.0f} "
                     f"rad/s of F = {f} N")
    revolutions = 8 if a.quick else 16
    with cf.ThreadPoolExecutor(a.jobs) as ex:
        results = list(ex.map(lambda p: study_point(out, p[0], p[1], revolutions), points))
    write_outputs(out, [r for rs in results for r in rs], a.quick)


if __name__ == "__main__":
    main()

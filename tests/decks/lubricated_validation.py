#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Validation of the lubricated 6208 from deck runs (doc/methods/lubricated_contact.md, "Validation
from runs"): the Hertz-zone capacitance against Hertz (Greenwood's area, the deck's) and
Hamrock-Dowson written out here from the runs' own loads and speeds, with its load and speed
exponents; the outer-zone factor over loads, speeds and temperatures; the regime from ohmic
to capacitive over speed, and the dry model recovered exactly without entrainment.
Usage: lubricated_validation.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import csv
import json
import math
import os
import subprocess

import numpy as np

from bearing_tests import read_signal, run_named_test
from deck_checks import check

# SKF 6208 (the deck's default, the paper's Table 1), the deck's steel, Nb balls.
RB, RINN, REXT, RCINN, RCEXT, NB = 0.0063, 0.024, 0.0366, 0.00655, 0.00665, 13
E_STAR = 2.0e11 / (2 * (1 - 0.3**2))  # Hertz's E* of steel on steel; E' = 2 E*
EPS0 = 8.8541878128e-12
TEND, DT, T0 = 0.02, 1e-5, 0.018  # steady rolling after the sliding phase (~12-15 ms)
# Operating points (omega rad/s, F N): three speeds and three loads, each in steady rolling by
# 18 ms (lighter loads at higher speeds still slide then: their entrainment is not rolling).
SPEEDS = [(300.0, 1000.0), (500.0, 1000.0), (800.0, 1000.0)]
LOADS = [(500.0, 320.0), (500.0, 640.0), (500.0, 1000.0)]
TINY_WET = 1e-6  # a wetted radius inside every Hertz ellipse: the gap adds nothing
SMOOTH = 2e-8    # roughness (m): lambda > 20, no metal, so Cb is the films' alone


def curvatures(inner):
    """A = 1/Rx (rolling), B = 1/Ry (across) of the ball on the inner or outer groove."""
    if inner:
        return 1 / RB + 1 / RINN, 1 / RB - 1 / RCINN
    return 1 / RB - 1 / REXT, 1 / RB - 1 / RCEXT


def hertz_zone(q, u, inner, eta, alpha):
    """eps0 pi a b / h_c of one contact with eps_r = 1: Greenwood's area a b = c^2 (the
    deck's area model; doc/methods/hertz_contact.md) over Hamrock and Dowson's central film."""
    A, B = curvatures(inner)
    r_eff = (A * B * (A + B) / 2) ** (-1 / 3)
    c2 = (3 * q * r_eff / (4 * E_STAR)) ** (2 / 3)
    rx, ep = 1 / A, 2 * E_STAR
    k = (A / B) ** (2 / 3)
    U, G, W = eta * u / (ep * rx), alpha * ep, q / (ep * rx * rx)
    hc = rx * 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1 - 0.61 * math.exp(-0.73 * k))
    return EPS0 * math.pi * c2 / hc


def steady_means(out):
    sig = read_signal(out)
    s = sig["time"] >= T0
    return {c: float(v[s].mean()) for c, v in sig.items()}


def run_point(r, name, omega, F, **var):
    out, _ = r.run(name, omega=omega, F=F, tend=TEND, dt=DT, nout=10, **var)
    return steady_means(out)


def eps_one_lubricant(r):
    """VG68 with eps_r = 1 at every temperature: Clausius-Mossotti then leaves the Hertz-zone
    permittivity at 1 whatever the pressure, and Cb is eps0 times pure geometry."""
    src = os.path.join(r.src, "inputs", "lubricants", "VG68")
    path = os.path.join(r.workdir, "VG68_eps1")
    with open(src) as f, open(path, "w") as g:
        for line in f:
            if line.startswith("variable eps_r "):
                line = "variable eps_r index 1.0\n"
            elif line.startswith("variable eps_slope "):
                line = "variable eps_slope index 0.0\n"
            g.write(line)
    return path


def test_capacitance(r):
    # The bearing's Cb from runs with only the Hertz zones (wetted radius inside the ellipses,
    # eps_r = 1, smooth surfaces) against Nb times the series of the inner and outer
    # eps0 pi a b / h_c computed above from each run's mean loads and rolling speeds.
    lub = eps_one_lubricant(r)
    rows = []
    for omega, F in sorted(set(SPEEDS + LOADS)):
        m = run_point(r, f"c_{omega:g}_{F:g}", omega, F, lubricant=lub, wetted=TINY_WET,
                      roughness=SMOOTH)
        wc, wi = m["omega_balls"], m["omega_inner"]
        qi, qo = m["fn_inner_mean"], m["fn_outer_mean"]
        ui, uo = (wi - wc) * RINN, wc * REXT
        meta = json.load(open(os.path.join(r.workdir, f"c_{omega:g}_{F:g}", "run.json")))
        ci = hertz_zone(qi, ui, True, meta["eta0"], meta["alpha_pv"])
        co = hertz_zone(qo, uo, False, meta["eta0"], meta["alpha_pv"])
        model = NB * ci * co / (ci + co)
        rows.append((omega, F, qi, qo, ui, uo, m["Cb"], model, m["lambda_min"], ci, co))
        print(f"     omega {omega:5g} F {F:4g}: Q {qi:6.2f}/{qo:6.2f} N, u {ui:5.2f}/{uo:5.2f} m/s, "
              f"Cb {m['Cb']:.5e} F, model {model:.5e} F ({m['Cb'] / model - 1:+.1e}), "
              f"lambda_min {m['lambda_min']:.0f}")
    # Tolerance: the model uses the mean load and speed of the run (the balls' loads differ
    # by ~1e-3, entering squared through the series and the 0.733 power): measured < 2e-4.
    worst = max(abs(row[6] / row[7] - 1) for row in rows)
    check(worst < 1e-3, f"Cb of the runs = Nb series(eps0 pi ab/h_c) from the runs' loads "
                        f"and speeds: worst {worst:.1e}")
    check(min(row[8] for row in rows) > 10, "lambda > 10: no metal in these runs")

    def slope(points, x):
        sel = [row for row in rows if (row[0], row[1]) in points]
        xs = np.log([x(row) for row in sel])
        return np.polyfit(xs, np.log([row[6] for row in sel]), 1)[0], \
            np.polyfit(xs, np.log([row[7] for row in sel]), 1)[0]

    # The exponents of the bearing's Cb: speed at F = 320 N, load at 500 rad/s (the balls'
    # loads follow F, and the centrifugal force adds to the outer ones).
    su, su_model = slope(SPEEDS, lambda row: row[0])
    sq, sq_model = slope(LOADS, lambda row: row[1])
    print(f"     d ln Cb / d ln omega = {su:.4f} (model {su_model:.4f}); "
          f"d ln Cb / d ln F = {sq:.4f} (model {sq_model:.4f})")
    check(abs(su - su_model) < 2e-3 and abs(sq - sq_model) < 2e-3,
          "the runs' Cb exponents are those of C ~ Q^0.733 u^-0.67 per contact")
    # The per-contact exponents themselves: fit C_j = C_j,model (Q_j/Q_j,ref)^(b - b0)
    # (u_j/u_j,ref)^(g - g0) in both contacts (ref: the 500 rad/s, 1000 N run) to the five
    # runs' Cb by Gauss-Newton; b0 = 2/3 + 0.067, g0 = -0.67 are the formula's.
    b0, g0 = 2 / 3 + 0.067, -0.67
    ref = next(row for row in rows if (row[0], row[1]) == (500.0, 1000.0))

    def predicted(b, g):
        out = []
        for row in rows:
            ci = row[9] * (row[2] / ref[2]) ** (b - b0) * (row[4] / ref[4]) ** (g - g0)
            co = row[10] * (row[3] / ref[3]) ** (b - b0) * (row[5] / ref[5]) ** (g - g0)
            out.append(math.log(NB * ci * co / (ci + co)))
        return np.array(out)

    y = np.log([row[6] for row in rows])
    x = np.array([b0, g0])
    for _ in range(8):
        f0 = predicted(*x)
        J = np.column_stack([(predicted(*(x + d)) - f0) / 1e-6 for d in np.eye(2) * 1e-6])
        x = x + np.linalg.lstsq(J, y - f0, rcond=None)[0]
    print(f"     per contact, fitted to the runs: C ~ Q^{x[0]:.4f} u^{x[1]:.4f} "
          f"(formula Q^{b0:.4f} u^{g0:.4f})")
    check(abs(x[0] - b0) < 5e-3, f"load exponent of the Hertz-zone capacitance from runs: {x[0]:.4f}")
    check(abs(x[1] - g0) < 5e-3, f"speed exponent of the Hertz-zone capacitance from runs: {x[1]:.4f}")


def test_outer_zone(r):
    # The outer-zone factor C_total / C_Hertz: VG68 with the deck's default wetted radius
    # (0.1 Db) against the same run with a wetted radius inside the ellipses, over loads,
    # speeds and temperatures. The bearing's factor lies between its inner and outer
    # contacts' (series).
    print("     omega   F    T   lambda  Cb total  Cb Hertz  factor")
    factors = []
    points = [(o, F, 40.0) for o, F in sorted(set(SPEEDS + LOADS))] + \
        [(500.0, 320.0, 70.0), (500.0, 320.0, 100.0)]
    for omega, F, T in points:
        tot = run_point(r, f"o_{omega:g}_{F:g}_{T:g}", omega, F, lubricant="VG68", temperature=T)
        hz = run_point(r, f"h_{omega:g}_{F:g}_{T:g}", omega, F, lubricant="VG68", temperature=T,
                       wetted=TINY_WET)
        f = tot["Cb"] / hz["Cb"]
        factors.append(f)
        print(f"     {omega:5g} {F:4g} {T:4g} {tot['lambda_min']:7.2f} {tot['Cb']:.3e} "
              f"{hz['Cb']:.3e} {f:6.2f}")
    # The gap outside the Hertz zone does not grow with the load nor thin with the film:
    # the factor falls as the load grows the ellipse and as the film thins. Expected within
    # the published band of 3 to 11 (doc/methods/lubricated_contact.md, where it falls and why).
    check(all(3.0 <= f <= 11.0 for f in factors),
          f"outer-zone factor of the bearing {min(factors):.2f} .. {max(factors):.2f} "
          f"(published band 3-11 measured on a roller bearing; ~3.5 for loaded ball bearings)")


def test_regime(r):
    # VG68 at 40 C and F = 320 N from standstill to the paper's speed: lambda from < 1 to > 3,
    # the phase of Z from near 0 to near -pi/2, |Z| from near the dry R to the capacitor's.
    print("     omega  lambda   Zphase      Zabs       R        Rb/R")
    res = []
    for omega in (2.0, 10.0, 30.0, 100.0, 500.0):
        m = run_point(r, f"r_{omega:g}", omega, 320.0, lubricant="VG68")
        res.append((omega, m["lambda_min"], m["Zphase"], m["Zabs"], m["R"], m["Rb"]))
        print(f"     {omega:5g} {m['lambda_min']:7.3f} {m['Zphase']:9.5f} {m['Zabs']:10.4g} "
              f"{m['R']:8.5f} {m['Rb'] / m['R']:9.4g}")
    lam = [x[1] for x in res]
    ph = [x[2] for x in res]
    check(lam[0] < 1 and lam[-1] > 3, f"lambda from {lam[0]:.2f} to {lam[-1]:.1f}")
    check(all(np.diff(ph) < 0), "the phase falls monotonically with speed")
    check(abs(ph[0]) < 0.05 and res[0][3] < 2 * res[0][4],
          f"lambda < 1: phase {ph[0]:.4f} rad near 0, |Z| {res[0][3]:.4g} within 2x of the dry R")
    check(abs(ph[-1] + math.pi / 2) < 1e-3, f"lambda > 3: phase {ph[-1]:.6f} near -pi/2")
    # No entrainment (omega 0, the balls at rest under the load): no film, metallic fraction
    # 1, each contact the dry one; at fexc = 1 Hz the gaps' susceptance (~1e-9 S against
    # ~0.1 S) is below rounding, so Rb is the dry closed form's R. The balls' residual
    # motion leaves some contacts a film of nearly nothing, whose non-metallic fraction
    # 1 - f = 0.8 lambda leaks area / (rho sigma) 0.8 h_min/h_c ~ 1e-13 S: 1e-12 of R with the
    # deck's sigma = 1e-7 m, rounding with sigma = 1e-3 m (lambda 1e4 times smaller).
    for sigma, tol in ((1e-7, 2e-12), (1e-3, 1e-15)):
        out, _ = r.run(f"r_0_{sigma:g}", omega=0.0, F=320.0, tend=0.002, dt=DT, nout=10,
                       lubricant="VG68", fexc=1.0, roughness=sigma)
        sig = read_signal(out)
        d = np.abs(sig["Rb"] / sig["R"] - 1)
        check(np.all(sig["lambda_min"] == 0), f"omega 0, sigma {sigma:g}: lambda_min = 0")
        check(d.max() < tol, f"omega 0, sigma {sigma:g} m: Rb = R to {d.max():.1e} "
                             f"({int(np.sum(d == 0))} of {len(d)} rows bit for bit)")


def test_regime_map(r):
    # studies/regime_map.py --quick (3 speeds x 2 temperatures): ohmic at 10 rad/s in oil at
    # 100 C (lambda ~ 0.2), capacitive at 1000 rad/s at 40 C (lambda ~ 18).
    out = os.path.join(r.workdir, "regime_map")
    env = dict(os.environ, OHMDEM=r.exe)
    subprocess.run(["/usr/bin/python3", os.path.join(r.src, "studies", "regime_map.py"),
                    "--quick", out], check=True, env=env, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(os.path.join(out, "regime_map.csv"))))
    ph = {(float(x["omega"]), float(x["temperature"])): float(x["Zphase"]) for x in rows}
    check(len(rows) == 6, "regime_map --quick: 6 runs")
    check(abs(ph[(10.0, 100.0)]) < 0.01, f"10 rad/s, 100 C: ohmic ({ph[(10.0, 100.0)]:.2e} rad)")
    check(abs(ph[(1000.0, 40.0)] + math.pi / 2) < 0.01,
          f"1000 rad/s, 40 C: capacitive ({ph[(1000.0, 40.0)]:.6f} rad)")
    check(all(ph[(w, t)] >= ph[(w2, t)] for (w, t) in ph for (w2, t2) in ph
              if t2 == t and w2 > w), "the phase falls with speed at each temperature")


if __name__ == "__main__":
    run_named_test({"capacitance": test_capacitance, "outer_zone": test_outer_zone,
                    "regime": test_regime, "regime_map": test_regime_map}, "ohmdem_lubval_")

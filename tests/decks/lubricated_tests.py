#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Deck-level tests of the lubricated 6208 (compute network/resistance keyword lubricant,
doc/methods/lubricated_contact.md). The film is checked against Hamrock and Dowson's formula written
out here from the run's own loads and speeds (not through the engine's code); the phase
against the capacitor's -pi/2; `lubricant none` against the dry run, byte for byte.
Usage: lubricated_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import json
import math
import os

import numpy as np

from bearing_tests import read_signal, run_named_test
from deck_checks import check

# SKF 6208 (the deck's default, the paper's Table 1) and the deck's steel.
RB, RINN, REXT, RCINN, RCEXT = 0.0063, 0.024, 0.0366, 0.00655, 0.00665
E_PRIME = 2.0e11 / (1 - 0.3**2)  # E' = E / (1 - nu^2) for steel on steel
DRY_COLUMNS = 20  # signal.txt of the dry deck
LUB_COLUMNS = ["Zabs", "Zphase", "Cb", "Rb", "hmin_inner", "hmin_outer", "lambda_min"]
TEND, DT = 0.016, 1e-5  # after the sliding phase (the deck's tslide, 15 ms) at 500 rad/s


def hamrock_dowson_min(w, u, rx, ry, eta, alpha):
    """Minimum film (Hamrock and Dowson 1977), k from Greenwood's ellipse (the deck's area)."""
    k = (ry / rx) ** (2.0 / 3.0)
    U, G, W = eta * u / (E_PRIME * rx), alpha * E_PRIME, w / (E_PRIME * rx * rx)
    return rx * 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1 - math.exp(-0.68 * k))


def steady(sig, t0=0.015):
    return sig["time"] >= t0


def test_paper_point(r):
    out, _ = r.run("vg68", lubricant="VG68", tend=TEND, dt=DT, nout=10)
    sig = read_signal(out)
    meta = json.load(open(os.path.join(out, "run.json")))
    for key in ["lubricant", "temperature", "eta0", "alpha_pv", "eps_r", "roughness", "fexc"]:
        check(key in meta, f"run.json records {key}")
    check(meta["lubricant"] == "VG68" and meta["temperature"] == 40.0, "run.json: VG68 at 40 C")
    # VG68 at 40 C: 68 mm^2/s times its density at 40 C (880 kg/m^3 at 15 C, 6.5e-4 1/K).
    check(abs(meta["eta0"] / (68e-6 * 880 * (1 - 6.5e-4 * 25)) - 1) < 1e-6, "run.json eta0")
    for c in LUB_COLUMNS:
        check(c in sig, f"signal.txt has the column {c}")
    s = steady(sig)
    lam = sig["lambda_min"][s]
    check(np.all(lam > 3), f"lambda > 3 at the paper's point (min {lam.min():.2f})")
    ph = sig["Zphase"][s]
    check(np.all(np.abs(ph + math.pi / 2) < 0.01),
          f"phase of Z near -pi/2 (capacitive): {ph.min():.6f} .. {ph.max():.6f} rad")
    cb = sig["Cb"][s]
    check(np.all((cb > 1e-11) & (cb < 1e-9)), f"Cb in tens to hundreds of pF: {cb.mean():.3e} F")
    # |Z| of the capacitor Cb at fexc (the conductance is negligible).
    zc = 1 / (2 * math.pi * meta["fexc"] * cb)
    check(np.all(np.abs(sig["Zabs"][s] / zc - 1) < 1e-3), "Zabs = 1/(omega Cb) for a capacitor")
    # The film from the run's loads and speeds: the minimum over the balls is the most loaded
    # contact's (h ~ Q^-0.073); its entrainment speed in rolling is (omega_i - omega_c) R_i
    # at the inner race, omega_c R_o at the outer (fixed) race.
    wc, wi = sig["omega_balls"][s], sig["omega_inner"][s]
    eta, alpha = meta["eta0"], meta["alpha_pv"]
    rx_i, ry_i = 1 / (1 / RB + 1 / RINN), 1 / (1 / RB - 1 / RCINN)
    rx_o, ry_o = 1 / (1 / RB - 1 / REXT), 1 / (1 / RB - 1 / RCEXT)
    h_i = np.array([hamrock_dowson_min(w, u, rx_i, ry_i, eta, alpha)
                    for w, u in zip(sig["fn_inner_max"][s], (wi - wc) * RINN)])
    h_o = np.array([hamrock_dowson_min(w, u, rx_o, ry_o, eta, alpha)
                    for w, u in zip(sig["fn_outer_max"][s], wc * REXT)])
    ei = np.abs(sig["hmin_inner"][s] / h_i - 1).max()
    eo = np.abs(sig["hmin_outer"][s] / h_o - 1).max()
    print(f"     hmin inner {sig['hmin_inner'][s].mean():.4e} m (formula {h_i.mean():.4e}), "
          f"outer {sig['hmin_outer'][s].mean():.4e} m (formula {h_o.mean():.4e})")
    # Tolerance: the run's speeds are the balls' own (a residual slip of a few 1e-4 after the
    # sliding phase, and the ball-to-ball spread of the loads), raised to 0.68: measured 1e-5.
    check(ei < 1e-3, f"hmin_inner against Hamrock-Dowson from the run's load and speed: {ei:.2e}")
    check(eo < 1e-3, f"hmin_outer against Hamrock-Dowson from the run's load and speed: {eo:.2e}")
    check(np.allclose(sig["lambda_min"][s],
                      np.minimum(sig["hmin_inner"][s], sig["hmin_outer"][s]) / meta["roughness"],
                      rtol=1e-12), "lambda_min = min(hmin) / roughness")


def test_none_unchanged(r):
    dry, _ = r.run("dry", tend=0.004, dt=DT, nout=10)
    none, _ = r.run("none", lubricant="none", tend=0.004, dt=DT, nout=10)
    lub, _ = r.run("lub", lubricant="VG68", tend=0.004, dt=DT, nout=10)
    a = open(os.path.join(dry, "signal.txt")).read()
    check(a == open(os.path.join(none, "signal.txt")).read(), "lubricant none: signal.txt identical")
    check(open(os.path.join(dry, "run.json")).read() == open(os.path.join(none, "run.json")).read(),
          "lubricant none: run.json identical")
    check(len(a.splitlines()[0].split()) == DRY_COLUMNS + 1, "lubricant none: no new column")
    # The lubricant changes no mechanics and no R: the dry columns of the lubricated run are
    # those of the dry run, to the last digit.
    rows_dry = [l.split()[:DRY_COLUMNS] for l in a.splitlines()[1:]]
    rows_lub = [l.split()[:DRY_COLUMNS] for l in open(os.path.join(lub, "signal.txt")).read().splitlines()[1:]]
    check(rows_dry == rows_lub, "with a lubricant the dry columns (R too) are unchanged")


def test_regime(r):
    # Thin oil, hot, slow: lambda < 1, the metal carries the current: phase near 0 and the
    # equivalent resistance at least the dry R (only a fraction of the Hertz area is metal).
    out, _ = r.run("thin", lubricant="VG32", temperature=100, omega=30, tend=0.004, dt=DT, nout=10)
    sig = read_signal(out)
    s = sig["time"] >= 0.002
    check(np.all(sig["lambda_min"][s] < 1), f"lambda < 1 (max {sig['lambda_min'][s].max():.2f})")
    check(np.all(np.abs(sig["Zphase"][s]) < 1e-3), f"phase near 0: |max| {np.abs(sig['Zphase'][s]).max():.2e}")
    check(np.all(sig["Rb"][s] >= sig["R"][s] * (1 - 1e-12)), "Rb >= the dry R")
    # A radial load: the balls outside the load zone touch one race only and couple to the
    # other through their gap (a capacitor in series): every output finite, still capacitive,
    # Cb below the isotropic run's (a gap of tens of micrometres holds less than a film of one).
    out, _ = r.run("radial", lubricant="VG68", load="radial", tend=TEND, dt=DT, nout=50)
    rad = read_signal(out)
    s = steady(rad)
    check(np.all(rad["n_contacts_race"][s] < 26), "radial: some balls touch one race only")
    check(all(np.all(np.isfinite(rad[c][s])) for c in LUB_COLUMNS), "radial: finite outputs")
    check(np.all(np.abs(rad["Zphase"][s] + math.pi / 2) < 0.01), "radial: capacitive")
    iso, _ = r.run("iso", lubricant="VG68", tend=TEND, dt=DT, nout=50)
    check(np.all(rad["Cb"][s] < read_signal(iso)["Cb"][s]), "radial: Cb below the isotropic run's")


def test_exponents(r):
    # d ln h_min / d ln u and d ln h_min / d ln Q measured from runs at three speeds and three
    # loads, against the formula's 0.68 and -0.073. Each run's own loads and speeds are used
    # (the centrifugal force moves the outer load with speed): the speed exponent is the slope
    # of ln(h Q^0.073) against ln u, the load exponent that of ln(h / u^0.68) against ln Q.
    def point(name, omega, F):
        out, _ = r.run(name, lubricant="VG68", omega=omega, F=F, tend=0.02, dt=DT, nout=10)
        sig = read_signal(out)
        s = sig["time"] >= 0.018
        wc = sig["omega_balls"][s].mean()
        return (sig["hmin_outer"][s].mean(), wc * REXT, sig["fn_outer_max"][s].mean())
    speeds = [point(f"w{w}", w, 1000.0) for w in (300.0, 500.0, 800.0)]
    loads = [point(f"F{F:g}", 500.0, F) for F in (250.0, 500.0, 1000.0)]
    h, u, q = (np.array(c) for c in zip(*speeds))
    slope_u = np.polyfit(np.log(u), np.log(h * q**0.073), 1)[0]
    h, u, q = (np.array(c) for c in zip(*loads))
    slope_q = np.polyfit(np.log(q), np.log(h / u**0.68), 1)[0]
    print(f"     d ln h/d ln u = {slope_u:.5f}, d ln h/d ln Q = {slope_q:.5f} (outer race)")
    check(abs(slope_u - 0.68) < 2e-3, "speed exponent of h_min from the runs: 0.68")
    check(abs(slope_q + 0.073) < 2e-3, "load exponent of h_min from the runs: -0.073")


def test_mpi(r):
    one, _ = r.run("mpi_1", lubricant="VG68", tend=0.003, dt=DT, nout=10)
    two, _ = r.run("mpi_2", lubricant="VG68", tend=0.003, dt=DT, nout=10, nprocs=2)
    a = open(os.path.join(one, "signal.txt")).read()
    check(a == open(os.path.join(two, "signal.txt")).read(),
          "lubricated: signal.txt identical with 1 and 2 processes")



def test_kernels(r):
    # The films' arithmetic: the plain kernel (one contact at a time, the reference) and the
    # lanes kernel (the default) give the same signal to the last digit, healthy and over an
    # inner pit (the strip's correction) with the films broken down (100 V at 20 MV/m: the ball
    # loop's breakdown branch).
    broken = dict(defect="inner", size=1, excitation=100, breakdown=2e7)
    for name, extra in (("healthy", {}), ("pit_breakdown", broken)):
        out = {}
        for kernel in ("plain", "lanes"):
            sim, _ = r.run(f"kernel_{kernel}_{name}", lubricant="VG68", kernel=kernel, tend=0.004,
                           dt=DT, nout=1, **extra)
            out[kernel] = open(os.path.join(sim, "signal.txt")).read()
        check(out["plain"] == out["lanes"],
              f"kernel plain and lanes: signal.txt identical ({name}, "
              f"{len(out['plain'].splitlines()) - 1} rows)")


def eta_vg68(t):
    """VG68's dynamic viscosity (Pa s) at t C, written out: ASTM D341 (Walther) through its
    40 and 100 C points, times the density 880 (1 - 6.5e-4 (t - 15)) kg/m^3."""
    ll = lambda nu: math.log10(math.log10(nu + 0.7))
    b = (ll(68) - ll(8.7)) / (math.log10(373.15) - math.log10(313.15))
    nu = 10 ** 10 ** (ll(68) - b * (math.log10(t + 273.15) - math.log10(313.15))) - 0.7
    return nu * 1e-6 * 880 * (1 - 6.5e-4 * (t - 15))


def test_temperature_laws(r):
    # A copy of VG68 with alpha measured at 30, 60 and 100 C (Stachowiak and Batchelor, Table
    # 2.3, the heavy machine oil that matches its viscosity) and Walden's resistivity from 40 C.
    src = open(os.path.join(r.src, "inputs", "lubricants", "VG68")).read()
    lines = [l for l in src.splitlines() if not l.startswith("variable alpha ")]
    lines += ["variable alpha_T1 index 30", "variable alpha_1 index 2.70e-8",
              "variable alpha_T2 index 60", "variable alpha_2 index 2.16e-8",
              "variable alpha_T3 index 100", "variable alpha_3 index 1.75e-8"]
    table = os.path.join(r.workdir, "VG68_table")
    walden = os.path.join(r.workdir, "VG68_walden")
    open(table, "w").write("\n".join(lines) + "\n")
    open(walden, "w").write("\n".join(lines + ["variable resistivity_tref index 40"]) + "\n")
    out, _ = r.run("table80", lubricant=table, temperature=80, tend=TEND, dt=DT, nout=10)
    meta = json.load(open(os.path.join(out, "run.json")))
    # ln alpha linear in T between 60 and 100 C, written out: 21.6 (17.5/21.6)^(20/40) 1/GPa.
    expected = 2.16e-8 * (1.75 / 2.16) ** 0.5
    check(abs(meta["alpha_pv"] / expected - 1) < 1e-8,
          f"run.json alpha_pv at 80 C from the table: {meta['alpha_pv']:.9g} (expected {expected:.9g})")
    # Walden: the resistivity, hence the oil's leakage G, follows the viscosity. With smooth
    # surfaces (sigma 10 nm: lambda > 30, a metallic fraction below erfc(21) ~ 1e-194) the oil
    # conducts alone, so Rb scales by eta(80) / eta(40).
    smooth = dict(temperature=80, roughness=1e-8, tend=TEND, dt=DT, nout=10)
    a = read_signal(r.run("plain80", lubricant=table, **smooth)[0])
    b = read_signal(r.run("walden80", lubricant=walden, **smooth)[0])
    s = steady(a)
    check(np.all(a["lambda_min"][s] > 30),
          f"sigma 10 nm at 80 C: lambda > 30 (no metal): min {a['lambda_min'][s].min():.1f}")
    want = eta_vg68(80) / eta_vg68(40)
    check(abs(meta["eta0"] / eta_vg68(80) - 1) < 1e-8, "run.json eta0 at 80 C (9 digits)")
    ratio = b["Rb"][s] / a["Rb"][s]
    worst = np.abs(ratio / want - 1).max()
    print(f"     Walden: Rb ratio against eta(80)/eta(40): worst relative difference {worst:.1e}")
    check(worst < 1e-9, f"Walden: Rb(80 C) scales by eta(80)/eta(40) = {want:.12f} "
                        f"({ratio.min():.12f} .. {ratio.max():.12f})")
    dc = np.abs(b["Cb"] / a["Cb"] - 1).max()
    # Cb moves only at second order in G / (omega C) (here about 3e-4).
    check(dc < 1e-6, f"Walden leaves Cb to second order in G/(omega C): {dc:.1e}")


if __name__ == "__main__":
    run_named_test({"paper_point": test_paper_point, "none_unchanged": test_none_unchanged,
                    "regime": test_regime, "exponents": test_exponents, "mpi": test_mpi,
                    "kernels": test_kernels,
                    "temperature_laws": test_temperature_laws},
                   "ohmdem_lub_")

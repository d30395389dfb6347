#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Deck-level tests of the SKF 6208 bearing scene (issue: the bearing runs).

Each test runs build/ohmdem on a deck in a fresh folder and checks the physics against
theory (kinematic frequencies, Hertz, centrifugal force, Stribeck load zone), never
against an earlier output of ours. Usage: bearing_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

import deck_checks
from deck_checks import check, finish

# SKF 6208, the paper's Table 1 and our deck defaults.
DB, DEXT, DINN, NB = 0.0126, 0.0732, 0.048, 13
RB = DB / 2
RP = (DEXT + DINN) / 4
RHO = 7800.0
BALL_MASS = RHO * 4.0 / 3.0 * math.pi * RB**3


def ftf_omega(omega_inner):
    """Cage angular speed of pure rolling (Harris, zero contact angle): 2*pi*FTF."""
    fr = omega_inner / (2 * math.pi)
    return 2 * math.pi * fr / 2 * (1 - DB / (2 * RP))


class Runner:
    def __init__(self, exe, src, workdir):
        self.exe, self.src, self.workdir = exe, src, workdir
        self.deck = os.path.join(src, "inputs", "bearing_6208", "in.bearing")

    def run(self, name, deck=None, nprocs=1, **var):
        out = os.path.join(self.workdir, name)
        os.makedirs(out, exist_ok=True)
        cmd = [self.exe, "-in", deck or self.deck, "-log", os.path.join(out, "log.txt"),
               "-screen", "none", "-var", "out", out]
        for k, v in var.items():
            cmd += ["-var", k, str(v)]
        if nprocs > 1:
            cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
        res = subprocess.run(cmd, cwd=out, capture_output=True, text=True)
        log = open(os.path.join(out, "log.txt")).read() if os.path.exists(
            os.path.join(out, "log.txt")) else ""
        if res.returncode != 0:
            sys.exit(f"FAIL: {' '.join(cmd)} exited {res.returncode}\n{res.stdout[-3000:]}"
                     f"\n{res.stderr[-3000:]}\n{log[-3000:]}")
        return out, log


def run_named_test(tests, prefix):
    """main() of a deck test driver: TEST --exe OHMDEM --src SOURCE_DIR, tests[TEST](runner)
    in a fresh folder (under $OHMDEM_KEEP_TEST_DIR when set, to keep it), then finish()."""
    p = argparse.ArgumentParser()
    p.add_argument("test", choices=sorted(tests))
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    a = p.parse_args()
    keep = os.environ.get("OHMDEM_KEEP_TEST_DIR")
    with tempfile.TemporaryDirectory(prefix=f"{prefix}{a.test}_", dir=keep) as wd:
        tests[a.test](Runner(os.path.abspath(a.exe), os.path.abspath(a.src), wd))
    finish()


def read_signal(folder):
    return deck_checks.read_signal(os.path.join(folder, "signal.txt"))


def sliding_end(sig, omega_inner, tol=0.01):
    """First time after which the cage speed stays within tol of pure rolling."""
    w = sig["omega_balls"]
    bad = np.nonzero(np.abs(w / ftf_omega(omega_inner) - 1) > tol)[0]
    if len(bad) == 0:
        return sig["time"][0]
    if bad[-1] + 1 >= len(w):
        return None
    return sig["time"][bad[-1] + 1]


def test_hertz_static(r):
    # Exact Hertz constants of the 6208 contacts, from scipy (tests/lib/contact/make_reference.py,
    # Johnson's elliptic solution with complete elliptic integrals), independent of our C++.
    k_ref = {"inner": 31035759069.643959, "outer": 29417740738.337234}
    geom = {"inner": (DINN / 2, 0.00655), "outer": (DEXT / 2, 0.00665)}
    deck = os.path.join(os.path.dirname(__file__), "in.hertz_static")
    for side in ("inner", "outer"):
        R, Rg = geom[side]
        for delta in (1e-7, 1e-6, 5e-6, 2e-5):
            x = R + RB - delta if side == "inner" else R - RB + delta
            _, log = r.run(f"hertz_{side}_{delta:g}", deck=deck, side=side, x=repr(x), R=R, Rg=Rg)
            fn = float(re.search(r"^HERTZ_FN (\S+)", log, re.M).group(1))
            ref = k_ref[side] * delta**1.5
            check(abs(fn / ref - 1) < 1e-3,
                  f"{side} delta={delta:g} m: Q = {fn:.6g} N, exact Hertz {ref:.6g} N "
                  f"(rel. error {fn / ref - 1:+.2e})")


def test_clear(r):
    deck = os.path.join(os.path.dirname(__file__), "in.clear")
    _, log = r.run("clear", deck=deck, bearing_deck=r.deck, tend=0.0002)
    check("CLEAR_OK" in log and log.count("BEARING_SUMMARY") >= 2,
          "bearing deck runs, clear, and runs again with our styles")


def steady_checks(sig, omega, F, label):
    t_slide = sliding_end(sig, omega)
    check(t_slide is not None, f"{label}: the sliding phase ends (cage within 1 % of 2*pi*FTF)")
    if t_slide is None:
        return
    print(f"     {label}: sliding phase lasts {t_slide * 1e3:.2f} ms")
    steady = sig["time"] > t_slide + 0.002
    w = sig["omega_balls"][steady].mean()
    ref = ftf_omega(omega)
    check(abs(w / ref - 1) < 0.01,
          f"{label}: ball set orbital speed {w:.4f} rad/s vs 2*pi*FTF = {ref:.4f} rad/s "
          f"({w / ref - 1:+.3%})")
    wc = sig["omega_cage"][steady].mean()
    check(abs(wc / ref - 1) < 0.01,
          f"{label}: cage body speed {wc:.4f} rad/s vs 2*pi*FTF ({wc / ref - 1:+.3%}); it floats "
          f"within its pocket play, contacts in {np.mean(sig['n_contacts_cage'][steady] > 0):.0%} "
          f"of the samples")
    dfn = (sig["fn_outer_mean"] - sig["fn_inner_mean"])[steady].mean()
    cf = BALL_MASS * w**2 * RP  # centrifugal force of a ball on the pitch circle at cage speed
    check(abs(dfn / cf - 1) < 0.05,
          f"{label}: outer - inner ball load {dfn:.4f} N vs centrifugal m*w^2*r = {cf:.4f} N "
          f"({dfn / cf - 1:+.2%})")
    fsum = sig["fn_outer_sum"][steady].mean()
    check(abs(fsum / F - 1) < 1e-3, f"{label}: outer reactions {fsum:.4f} N balance F = {F} N")
    check(np.all(sig["n_contacts_race"][steady] == 2 * NB), f"{label}: all 26 race contacts held")


def test_kinematics(r, omega, tend, F=320.0):
    out, log = r.run(f"kin_{omega:g}", omega=omega, tend=tend, nout=10, F=F)
    sig = read_signal(out)
    steady_checks(sig, omega, F, f"omega = {omega:g} rad/s, F = {F:g} N")
    m = re.search(r"^BEARING_SUMMARY .* z_extent (\S+) spin_xy_max (\S+)", log, re.M)
    check(float(m.group(1)) == 0.0 and float(m.group(2)) == 0.0,
          "2D: ball centres stay in z = 0 and balls spin about z only")


def greenwood_area(fn, A, B, E_eff):
    """Paper eqs. 2-5 (Greenwood 1985): rigid Hertz contact area from the normal force."""
    r_eff = (A * B * (A + B) / 2) ** (-1 / 3)
    c = (3 * fn * r_eff / (4 * E_eff)) ** (1 / 3)
    return math.pi * c * c


def test_resistance(r):
    # Independent closed form: each ball is one eq. 1 resistor between its outer and inner
    # contact points, which face each other (theta = pi, 1 - cos = 2):
    # C = gamma*S_out*S_in/(4*V); the 13 balls carry equal loads, so R = 1/(13*C).
    out, log = r.run("resistance", tend=0.025, nout=10)
    sig = read_signal(out)
    t_slide = sliding_end(sig, 500.0)
    steady = sig["time"] > t_slide + 0.002
    R = sig["R"][steady]
    fluct = (R.max() - R.min()) / R.mean()
    print(f"     healthy R = {R.mean():.6f} ohm, relative fluctuation (max-min)/mean = {fluct:.2e}")
    check(np.all(np.isfinite(sig["R"])), "R is finite at every output step")
    E_eff = 2e11 / (2 * (1 - 0.3**2))
    gamma = 5.88e7
    V = 4 / 3 * math.pi * RB**3
    s_in = greenwood_area(sig["fn_inner_mean"][steady], 1 / RB + 1 / (DINN / 2), 1 / RB - 1 / 0.00655, E_eff)
    s_out = greenwood_area(sig["fn_outer_mean"][steady], 1 / RB - 1 / (DEXT / 2), 1 / RB - 1 / 0.00665, E_eff)
    r_ref = 1 / (NB * gamma * s_in * s_out / (4 * V))
    err = np.max(np.abs(R / r_ref - 1))
    check(err < 1e-9, f"R equals the parallel sum of 13 eq. 1 ball resistors (max rel. error {err:.1e})")
    # The paper's healthy value (Machado et al. 2014, Fig. 9b): 1.39 ohm; F = 320 N is the load
    # that gives it with the Greenwood areas (inputs/bearing_6208/in.bearing,
    # doc/bearing_catalog.md).
    check(abs(R.mean() / 1.39 - 1) < 0.03, f"R = {R.mean():.4f} ohm vs the paper's 1.39 ohm "
          f"({R.mean() / 1.39 - 1:+.2%})")
    check(fluct < 1e-6, "R is steady after the sliding phase")
    gen, _ = r.run("resistance_general", tend=0.025, nout=10, closedform="no")
    Rg = read_signal(gen)["R"]
    dg = np.max(np.abs(Rg / sig["R"] - 1))
    check(dg < 1e-12, f"closed form (a resistor per ball) = general network solve "
          f"(max rel. diff {dg:.1e})")
    out2, _ = r.run("resistance_exact", tend=0.025, nout=10, area="exact")
    Rx = read_signal(out2)["R"][steady].mean()
    print(f"     area exact: R = {Rx:.6f} ohm ({Rx / R.mean() - 1:+.2%} vs greenwood)")

    # Holm: a ball between two races is the series sum of its two constrictions
    # R_c = rho*K(e^2)/(pi*a) (elliptic spot, Holm 1967; K from scipy), 13 balls in parallel.
    from scipy.special import ellipk

    def holm(fn, A, B):
        c = np.sqrt(greenwood_area(fn, A, B, E_eff) / math.pi)
        kappa = (max(A, B) / min(A, B)) ** (2 / 3)
        a, b = c * math.sqrt(kappa), c / math.sqrt(kappa)
        return ellipk(1 - (b / a) ** 2) / (gamma * math.pi * a)

    geo_in = (1 / RB + 1 / (DINN / 2), 1 / RB - 1 / 0.00655)
    geo_out = (1 / RB - 1 / (DEXT / 2), 1 / RB - 1 / 0.00665)
    for model in ("holm", "eq1+holm"):
        out3, _ = r.run(f"resistance_{model}", tend=0.025, nout=10, emodel=model)
        s3 = read_signal(out3)
        rc = (holm(s3["fn_inner_mean"][steady], *geo_in) + holm(s3["fn_outer_mean"][steady], *geo_out))
        if model == "eq1+holm":
            s_in3 = greenwood_area(s3["fn_inner_mean"][steady], *geo_in, E_eff)
            s_out3 = greenwood_area(s3["fn_outer_mean"][steady], *geo_out, E_eff)
            rc = rc + 4 * V / (gamma * s_in3 * s_out3)
        ref3 = rc / NB
        err3 = np.max(np.abs(s3["R"][steady] / ref3 - 1))
        check(err3 < 1e-9, f"model {model}: R = {s3['R'][steady].mean():.6g} ohm = series sum per "
              f"ball, 13 in parallel (max rel. error {err3:.1e})")


def test_radial(r):
    # Static radial load on the outer ring, a ball on the load line: Stribeck's load-zone
    # sum for zero clearance, Q_max = Fr / sum_j cos^(3/2+1)(psi_j) over loaded balls (point
    # contact), 13 balls: sum = 2.9725, so Q_max = 4.373*Fr/Nb (Harris, Rolling Bearing
    # Analysis, ch. 7; the classical "4.37" holds for any Z large enough).
    psi = 2 * np.pi * np.arange(NB) / NB
    c = np.cos(psi)
    zeta = np.sum(c[c > 0] ** 2.5)
    factor = NB / zeta
    Fr = 2000.0
    # The outer ring is pushed along -y: its top part meets the balls there (load zone at +y).
    out, _ = r.run("radial", load="radial", F=Fr, omega=0.0, phase=90.0, tend=0.004, nout=10)
    read_signal(out)  # signal.txt must be written and parse, though the check reads the log
    # f_outer[8] (max ball load) is not in signal.txt; the log has it from the thermo line.
    log = open(os.path.join(out, "log.txt")).read()
    qmax = float(re.search(r"^RADIAL_QMAX (\S+)", log, re.M).group(1)) if "RADIAL_QMAX" in log else None
    check(qmax is not None, "radial: maximum ball load reported")
    if qmax is None:
        return
    got = qmax / (Fr / NB)
    check(abs(got / factor - 1) < 0.02,
          f"radial: Q_max = {got:.4f}*Fr/Nb vs Stribeck {factor:.4f}*Fr/Nb ({got / factor - 1:+.2%})")


def test_restart(r):
    full, _ = r.run("restart_full", tend=0.004)
    first, _ = r.run("restart_first", deck=os.path.join(os.path.dirname(__file__),
                                                        "in.restart_first"),
                     bearing_deck=r.deck, tend=0.002)
    second, _ = r.run("restart_second", tend=0.004, start="restart",
                      restart_file=os.path.join(first, "half.restart"))
    a = open(os.path.join(full, "signal.txt")).read().splitlines()
    b = open(os.path.join(second, "signal.txt")).read().splitlines()
    tail = a[-(len(b) - 1):]
    check(len(b) > 1 and tail == b[1:],
          f"restart: the second half ({len(b) - 1} rows) is identical to the single run")


def test_mpi(r):
    one, _ = r.run("mpi_1", tend=0.003)
    two, _ = r.run("mpi_2", tend=0.003, nprocs=2)
    a = open(os.path.join(one, "signal.txt")).read()
    b = open(os.path.join(two, "signal.txt")).read()
    check(a == b, "MPI: the signal is identical with 1 and 2 processes")


def test_stability(r, dt):
    # At the documented largest stable step and at twice the paper's speed: no blow-up, no
    # energy growth (the steady state must be the same rolling state). At 1000 rad/s the
    # centrifugal force (39 N) exceeds F/Nb at F = 320 N: the inner contacts unload and the
    # balls skid, so this runs at F = 1000 N, where they roll.
    F = 1000.0
    out, _ = r.run(f"stab_{dt:g}", dt=dt, omega=1000.0, F=F, tend=0.05, nout=max(1, round(1e-5 / dt)))
    sig = read_signal(out)
    check(np.all(np.isfinite(sig["fn_outer_mean"])), f"dt = {dt:g} s: finite forces")
    steady_checks(sig, 1000.0, F, f"dt = {dt:g} s, omega = 1000 rad/s")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test")
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    p.add_argument("--dt", type=float, default=1e-6)
    a = p.parse_args()
    keep = os.environ.get("OHMDEM_KEEP_TEST_DIR")
    with tempfile.TemporaryDirectory(prefix=f"ohmdem_{a.test}_", dir=keep) as wd:
        r = Runner(os.path.abspath(a.exe), os.path.abspath(a.src), wd)
        {
            "hertz_static": lambda: test_hertz_static(r),
            "clear": lambda: test_clear(r),
            "kinematics_500": lambda: test_kinematics(r, 500.0, 0.025),
            "kinematics_250": lambda: test_kinematics(r, 250.0, 0.02),
            "radial": lambda: test_radial(r),
            "resistance": lambda: test_resistance(r),
            "restart": lambda: test_restart(r),
            "mpi": lambda: test_mpi(r),
            "stability": lambda: test_stability(r, a.dt),
        }[a.test]()
    finish()


if __name__ == "__main__":
    main()

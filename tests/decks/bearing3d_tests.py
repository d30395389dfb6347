#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Deck tests of the 3D bearing (inputs/bearing_6208/in.bearing with -var model 3d) against
numbers nobody here made: the Jones-Harris equilibrium written out from Harris
(jones_harris.py, itself checked by jones_harris_tests.py) for each ball's load and contact
angle and the shaft's displacement; Harris' pure-thrust relation; the planar scene (model 2d)
in the planar limit; the kinematics of rolling with the contact angle; stability and the
errors of impossible geometries. The static runs are frictionless (mu 0): the Jones-Harris
equilibrium is, and with friction a bearing at rest keeps the stick of its loading path
(doc/methods/bearing_3d.md, "Friction").
Usage: bearing3d_tests.py TEST --exe OHMDEM --src SOURCE_DIR [--dt DT]
"""
import math
import os
import re

import numpy as np

import jones_harris as jh
from bearing_tests import read_signal, run_named_test
from deck_checks import check

# The deck's default bearing (machado2014, the paper's Table 1) and materials.
NB, DB, DPW, RCI, RCO = 13, 0.0126, 0.0606, 0.00655, 0.00665
E_STAR = 2e11 / (2 * (1 - 0.3**2))
DT = 1e-6  # the 3D runs carry loads of hundreds of N per ball: 1e-5 s is past their
#             stable step (the planar decks run 1e-5 at a few tens of N); --dt sets it


def read_dump_last(path):
    """The last snapshot of a LIGGGHTS custom dump: a dict of columns, sorted by id."""
    lines = open(path).read().splitlines()
    start = max(i for i, s in enumerate(lines) if s.startswith("ITEM: ATOMS"))
    names = lines[start].split()[2:]
    rows = np.array([[float(x) for x in s.split()] for s in lines[start + 1:] if s.strip()])
    rows = rows[np.argsort(rows[:, 0])]
    return {n: rows[:, k] for k, n in enumerate(names)}


def run3d(r, name, **var):
    var.setdefault("dt", DT)
    var.setdefault("model", "3d")
    out, log = r.run(name, **var)
    return out, log, read_signal(out)


def static_run(r, name, tend=0.03, **var):
    """A frictionless bearing at rest, settled under its loads: the last step's balls."""
    var.update(omega=0, mu=0, tend=tend, nout=max(1, round(1e-4 / DT)),
               dumpraces=round(tend / DT))
    out, log, sig = run3d(r, name, **var)
    return sig, read_dump_last(os.path.join(out, "races.dump"))


def compare_balls(label, d, Q, alpha, tol=0.01, alpha_inner=None):
    """Each ball's load (both races) and contact angle against Jones-Harris: loads within tol
    of the largest load, and within tol of their own where they carry over a third of it;
    angles within tol where loaded. A race's angle is measured in its own ring's frame: the
    inner one's (alpha_inner) differs from the outer one's by the shaft's tilt."""
    qmax = Q.max()
    worst_q = worst_a = 0.0
    for side in ("inner", "outer"):
        fn, a = d[f"f_{side}[1]"], np.radians(d[f"f_{side}[8]"])
        ref = alpha_inner if side == "inner" and alpha_inner is not None else alpha
        big = Q > qmax / 3
        worst_q = max(worst_q, np.max(np.abs(fn - Q)) / qmax, np.max(np.abs(fn[big] / Q[big] - 1)))
        worst_a = max(worst_a, np.max(np.abs(a[big] / ref[big] - 1)))
    check(worst_q < tol and worst_a < tol,
          f"{label}: each ball's load and contact angle against Jones-Harris (worst "
          f"{worst_q:.2e} and {worst_a:.2e}, within {tol:.0%}; Qmax {qmax:.2f} N)")
    return worst_q, worst_a


def test_static_axial(r):
    for Pd in (0.0, 20e-6):
        Fa = 500.0
        sig, d = static_run(r, f"axial_{Pd * 1e6:.0f}", Fr=0, Fa=Fa, clearance=Pd)
        psi = np.arctan2(d["y"], d["x"])
        b = jh.Bearing(NB, DB, DPW, RCI, RCO, E_STAR, clearance=Pd)
        q, (Q, alpha, _, _, _), _ = jh.solve(b, psi, [0, 0, Fa])
        label = f"Fa {Fa:g} N, clearance {Pd * 1e6:g} um"
        compare_balls(label, d, Q, alpha)
        da = sig["delta_a"][-1]
        check(abs(da / q[2] - 1) < 0.01, f"   delta_a {da * 1e6:.4f} um, Jones-Harris "
              f"{q[2] * 1e6:.4f} um ({da / q[2] - 1:+.1e})")
        a_h = math.degrees(jh.harris_axial_angle(b, Fa))
        a_in, a_out = sig["alpha_inner_mean"][-1], sig["alpha_outer_mean"][-1]
        check(abs(a_in - a_h) < 0.2 and abs(a_out - a_h) < 0.2,
              f"   alpha {a_in:.4f} / {a_out:.4f} deg (inner / outer), Harris' thrust relation "
              f"{a_h:.4f} deg (within 0.2 deg)")
        each = Fa / (NB * np.sin(np.radians(d["f_inner[8]"])))
        off = np.max(np.abs(d["f_inner[1]"] / each - 1))
        check(off < 0.01, f"   every ball Fa/(Z sin a) = {each.mean():.3f} N (worst {off:.1e})")


def test_static_combined(r):
    cases = (("radial", 2000.0, 0.0, 0.0), ("combined", 1500.0, 800.0, 10e-6))
    for name, Fr, Fa, Pd in cases:
        sig, d = static_run(r, name, Fr=Fr, Fa=Fa, clearance=Pd, tend=0.04)
        psi = np.arctan2(d["y"], d["x"])
        b = jh.Bearing(NB, DB, DPW, RCI, RCO, E_STAR, clearance=Pd)
        q, (Q, alpha, _, u, _), _ = jh.solve(b, psi, [0, Fr, Fa])  # the shaft pushed along +y
        label = f"Fr {Fr:g} N, Fa {Fa:g} N, clearance {Pd * 1e6:g} um"
        if Fa == 0:
            # No contact angle: compare the loads only (alpha = 0 has no relative error).
            fn = d["f_inner[1]"]
            worst = np.max(np.abs(fn - Q)) / Q.max()
            check(worst < 0.01 and np.max(np.abs(d["f_inner[8]"])) < 1e-6,
                  f"{label}: each ball's load against Jones-Harris (worst {worst:.2e} of Qmax "
                  f"{Q.max():.2f} N), contact angles 0")
        else:
            compare_balls(label, d, Q, alpha, alpha_inner=jh.ring_frame_angles(q, u))
        dr, da = sig["delta_r"][-1], sig["delta_a"][-1]
        ok = abs(dr / q[1] - 1) < 0.01 and (Fa == 0 or abs(da / q[2] - 1) < 0.01)
        check(ok, f"   delta_r {dr * 1e6:.4f} um (JH {q[1] * 1e6:.4f}), delta_a {da * 1e6:.4f} um"
              f" (JH {q[2] * 1e6:.4f}), tilt {sig['tilt'][-1]:.3e} rad (JH {-q[3]:.3e})")


def test_angular_contact(r):
    a0, preload, Fr = 25.0, 15e-6, 800.0
    sig, d = static_run(r, "angular", Fr=Fr, alpha0=a0, preload=preload, tend=0.04)
    psi = np.arctan2(d["y"], d["x"])
    b = jh.Bearing(NB, DB, DPW, RCI, RCO, E_STAR, alpha0_deg=a0)
    q, (Q, alpha, _, u, _), _ = jh.solve(b, psi, [0, Fr, 0], preload=preload)
    compare_balls(f"alpha0 {a0:g} deg, preload {preload * 1e6:g} um, Fr {Fr:g} N", d, Q, alpha,
                  alpha_inner=jh.ring_frame_angles(q, u))
    axial = float(np.sum(Q * u[:, 2]))
    dem_axial = float(np.sum(d["f_inner[1]"] * np.sin(np.radians(d["f_inner[8]"]))))
    tilt_jh = -q[3]  # about z x (0, 1, 0) = -x
    check(abs(dem_axial / axial - 1) < 0.01 and abs(sig["delta_r"][-1] / q[1] - 1) < 0.01 and
          abs(sig["tilt"][-1] / tilt_jh - 1) < 0.01,
          f"   axial reaction {dem_axial:.2f} N (JH {axial:.2f}), delta_r "
          f"{sig['delta_r'][-1] * 1e6:.4f} um (JH {q[1] * 1e6:.4f}), tilt "
          f"{sig['tilt'][-1] * 1e3:.4f} mrad (JH {tilt_jh * 1e3:.4f})")


def test_planar_limit(r):
    # The paper's scene under a radial load (model 2d, the outer ring pressed along -y) and the
    # 3D bearing with no clearance and no axial load (the shaft pressed along +y): the same
    # relative displacement, the same load zone.
    F = 2000.0
    common = dict(omega=0, mu=0, tend=0.03, nout=max(1, round(1e-4 / DT)), dt=DT,
                  dumpraces=round(0.03 / DT))
    o2, _ = r.run("planar_2d", load="radial", F=F, **common)
    o3, _ = r.run("planar_3d", model="3d", Fr=F, **common)
    s2, s3 = read_signal(o2), read_signal(o3)
    d2 = read_dump_last(os.path.join(o2, "races.dump"))
    d3 = read_dump_last(os.path.join(o3, "races.dump"))
    qmax = d2["f_inner[1]"].max()
    worst = max(np.max(np.abs(d3[f"f_{s}[1]"] - d2[f"f_{s}[1]"])) for s in ("inner", "outer"))
    dR = s3["R"][-1] / s2["R"][-1] - 1
    check(worst / qmax < 1e-3 and abs(dR) < 1e-3,
          f"at rest, Fr {F:g} N: ball loads as model 2d's within {worst / qmax:.1e} of Qmax "
          f"{qmax:.2f} N, R {s3['R'][-1]:.6f} ohm vs {s2['R'][-1]:.6f} ({dR:+.1e})")
    # Rolling at the paper's speed with friction: the means over the steady window.
    roll = dict(omega=500, tend=0.04, nout=max(1, round(1e-4 / DT)), dt=DT)
    o2, _ = r.run("planar_2d_rolling", load="radial", F=F, **roll)
    o3, _ = r.run("planar_3d_rolling", model="3d", Fr=F, **roll)
    s2, s3 = read_signal(o2), read_signal(o3)
    w = s2["time"] > 0.025
    for col in ("fn_inner_max", "fn_outer_max", "R"):
        rel = s3[col][w].mean() / s2[col][w].mean() - 1
        check(abs(rel) < 1e-3, f"rolling at 500 rad/s: mean {col} {s3[col][w].mean():.6g} vs "
              f"model 2d {s2[col][w].mean():.6g} ({rel:+.1e}, within 1e-3)")


def test_kinematics(r):
    # Rolling under a pure axial load: every ball at the contact angle alpha. Pure rolling
    # (Harris) with gamma = D cos(alpha)/dm: cage w_i (1 - gamma)/2; the ball's rolling speed
    # about an axis across its contact line, in the cage's frame, w_c (dm/D)(1 + gamma).
    omega, Fa = 500.0, 1000.0
    out, log, sig = run3d(r, "kinematics", omega=omega, Fr=0, Fa=Fa, clearance=20e-6, tend=0.06,
                          nout=max(1, round(1e-4 / DT)), dumpraces=round(0.06 / DT))
    w = sig["time"] > 0.04
    a = np.radians(0.5 * (sig["alpha_inner_mean"][w] + sig["alpha_outer_mean"][w]).mean())
    g = DB * math.cos(a) / DPW
    kin = omega * (1 - g) / 2
    planar = omega * (1 - DB / DPW) / 2
    wc = sig["omega_balls"][w].mean()
    slip = wc / kin - 1
    check(abs(slip) < 0.25 * abs(kin / planar - 1),
          f"cage {wc:.4f} rad/s, pure rolling at alpha {math.degrees(a):.3f} deg {kin:.4f} rad/s "
          f"(the run's slip {slip:+.2e}); the planar kinematics {planar:.4f} would be "
          f"{planar / wc - 1:+.2e} off")
    d = read_dump_last(os.path.join(out, "races.dump"))
    p_in = np.stack([d["f_inner[4]"], d["f_inner[5]"], d["f_inner[7]"]], axis=1)
    p_out = np.stack([d["f_outer[4]"], d["f_outer[5]"], d["f_outer[7]"]], axis=1)
    n = p_out - p_in
    n /= np.linalg.norm(n, axis=1)[:, None]
    wb = np.stack([d["omegax"], d["omegay"], d["omegaz"] - wc], axis=1)  # in the cage's frame
    spin = np.sum(wb * n, axis=1)
    roll = np.linalg.norm(wb - spin[:, None] * n, axis=1)
    ref = wc * DPW / DB * (1 + g)
    err = np.max(np.abs(roll / ref - 1))
    check(err < max(0.01, 3 * abs(slip)),
          f"ball rolling speed {roll.mean():.2f} rad/s vs w_c (dm/D)(1 + gamma) = {ref:.2f} rad/s "
          f"(worst {err:.2e})")
    # The spin about the contact line: no relative spin on the outer race (Jones' outer-race
    # control) is -w_c sin(alpha) in the cage's frame, none on the inner race (w_i - w_c)
    # sin(alpha); where the two spin moments balance each other it lies between.
    outer_control, inner_control = -wc * math.sin(a), (omega - wc) * math.sin(a)
    check(outer_control < spin.mean() < inner_control and np.ptp(spin) < 0.05 * roll.mean(),
          f"spin about the contact line {spin.mean():+.2f} rad/s ({spin.mean() / roll.mean():+.3f}"
          f" of the rolling speed), between outer-race control {outer_control:+.2f} and "
          f"inner-race control {inner_control:+.2f} rad/s")


def static_rating_axial(b):
    """The pure axial load at which the inner contact's peak Hertz pressure reaches 4200 MPa
    (ISO 76's static rating of ball bearings), from Harris' Hertz ellipse (jones_harris.py)."""
    from scipy.optimize import brentq

    def excess(Fa):
        a = jh.harris_axial_angle(b, Fa)
        Q = Fa / (b.Z * math.sin(a))
        return jh.peak_pressure(b, Q, a, True) - 4.2e9

    return brentq(excess, 10.0, 1e6, rtol=1e-6)


def no_nan_no_loss(sig, log, label):
    # R is infinite while no ball touches both races (the play not yet taken up): no NaN, and
    # finite at the end.
    finite = not any(np.any(np.isnan(v)) for v in sig.values()) and np.isfinite(sig["R"][-1])
    m = re.search(r"^BEARING_SUMMARY .* z_extent (\S+)", log, re.M)
    check(finite and m is not None and sig["n_contacts_race"][-1] > 0,
          f"{label}: finished, no NaN, every ball kept (z extent {float(m.group(1)) * 1e6:.1f} um)"
          if m else f"{label}: did not finish")


def test_stability(r):
    b = jh.Bearing(NB, DB, DPW, RCI, RCO, E_STAR)
    c0a = static_rating_axial(b)
    print(f"     static axial rating (4200 MPa at the inner contacts): {c0a:.0f} N")
    for Fa in (1.0, c0a):
        _, log, sig = run3d(r, f"stab_axial_{Fa:.0f}", Fr=0, Fa=Fa, omega=500, tend=0.01,
                            nout=10)
        no_nan_no_loss(sig, log,
                       f"Fa {Fa:.0f} N at 500 rad/s, alpha {sig['alpha_inner_mean'][-1]:.2f} deg")
    _, log, sig = run3d(r, "stab_clearance", Fr=1000, Fa=200, clearance=50e-6, omega=500,
                        tend=0.01, nout=10)
    no_nan_no_loss(sig, log, f"clearance 50 um, Fr 1000 N, Fa 200 N, alpha up to "
                   f"{sig['alpha_outer_max'][-1]:.2f} deg")
    _, log, sig = run3d(r, "stab_alpha45", Fr=500, alpha0=45, preload=10e-6, omega=500,
                        tend=0.01, nout=10)
    no_nan_no_loss(sig, log, f"alpha0 45 deg under preload, alpha {sig['alpha_inner_mean'][-1]:.2f}"
                   " deg")
    _, log, sig = run3d(r, "stab_fast", Fr=2000, Fa=500, omega=2000, tend=0.01, nout=10,
                        dt=min(DT, 5e-6))
    no_nan_no_loss(sig, log, "2000 rad/s (19 100 r/min), Fr 2000 N, Fa 500 N")


def expect_error(r, name, pattern, **var):
    var.setdefault("model", "3d")
    var.setdefault("tend", 1e-4)
    out = os.path.join(r.workdir, name)
    os.makedirs(out, exist_ok=True)
    import subprocess
    cmd = [r.exe, "-in", r.deck, "-log", os.path.join(out, "log.txt"), "-screen", "none",
           "-var", "out", out]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    res = subprocess.run(cmd, cwd=out, capture_output=True, text=True)
    text = res.stdout + res.stderr + open(os.path.join(out, "log.txt")).read()
    check(res.returncode != 0 and re.search(pattern, text) is not None,
          f"{name}: stops (exit {res.returncode}) with '{pattern}'")


def test_errors(r):
    A = RCI + RCO - DB
    expect_error(r, "err_model", r"deck variable model: expected 2d or 3d, got '3D'", model="3D")
    expect_error(r, "err_clearance", r"lets the ball pass between the grooves",
                 clearance=2.2 * A)
    expect_error(r, "err_shoulder", r"past the shoulder at 15 deg", shoulder=15, Fr=0, Fa=5000,
                 tend=0.01)
    expect_error(r, "err_both", r"keyword 'alpha0' expects 0 with a clearance", clearance=1e-5,
                 alpha0=25)


def test_defect_width(r):
    # Under a pure axial load every contact runs on the outer race's groove at alpha (13 deg,
    # Rg alpha = 1.5 mm from its bottom). A pit across the whole track is met by every ball; one
    # 1 mm wide at the bottom lies beside their path and is never felt; the same pit centred on
    # the path (track alpha) is.
    case = dict(Fr=0, Fa=500, clearance=20e-6, omega=500, defect="outer", size=3, tend=0.03,
                nout=10)
    runs = {}
    for name, extra in (("whole", {}), ("beside", {"dwidth": 1e-3}),
                        ("on_path", {"dwidth": 1e-3, "dtrack": 13.0})):
        _, _, sig = run3d(r, f"pit_{name}", **case, **extra)
        w = sig["time"] > 0.015
        runs[name] = (sig["n_masked"][w].max(), sig["R"][w].max() / sig["R"][w].min() - 1,
                      sig["alpha_outer_mean"][w].mean())
    a = runs["whole"][2]
    off = RCO * math.radians(a) * 1e3
    check(runs["whole"][0] >= 1 and runs["whole"][1] > 0.05,
          f"a pit across the whole track masks the passing balls (R up {runs['whole'][1]:.1%})")
    check(runs["beside"][0] == 0 and runs["beside"][1] < 0.01,
          f"a 1 mm pit at the groove bottom, {off:.2f} mm beside the contact path (alpha {a:.2f} "
          f"deg): never masked, R within {runs['beside'][1]:.2%}")
    check(runs["on_path"][0] >= 1 and runs["on_path"][1] > 0.05,
          f"the same pit on the path (track 13 deg): masked, R up {runs['on_path'][1]:.1%}")


def masked_events(sig, t0):
    """The times at which the defective ball's contacts enter its pit (n_masked rising from 0)
    after t0."""
    t, on = sig["time"], sig["n_masked"] > 0
    rise = np.nonzero(on[1:] & ~on[:-1])[0] + 1
    return t[rise][t[rise] > t0]


def test_ball_defect(r):
    # A 20 deg pit on ball 1 (position 0: outward at the start), rolling at 500 rad/s under
    # 1000 N axial with a 20 um clearance (alpha 14.5 deg). The ball turns about its rolling
    # axis, across its contact line: a pit on the contact line at the start (latitude alpha)
    # lies on the path of both contacts and meets one every half turn of the ball in the cage's
    # frame, 1 / (2 BSF) apart with BSF = w_c (dm/D)(1 + gamma) / (2 pi); a pit at the ball's
    # pole (latitude 90 deg, 14.5 deg from the rolling axis) is never met. (The ball's spin
    # about its contact line, 0.05 of its rolling, tilts its axis of rotation by 2.8 deg: the
    # contact opposite the one the pit starts on passes 5.6 deg from the pit's centre, so that a
    # pit of 10 deg meets only one contact a turn.)
    base = dict(omega=500, Fr=0, Fa=1000, clearance=20e-6, defect="ball", size=20, position=0,
                tend=0.06, nout=10)
    _, _, on_path = run3d(r, "ball_on_path", dtrack=14.5, **base)
    _, _, pole = run3d(r, "ball_pole", dtrack=90, **base)
    w = on_path["time"] > 0.03
    a = np.radians(0.5 * (on_path["alpha_inner_mean"][w] + on_path["alpha_outer_mean"][w]).mean())
    g = DB * math.cos(a) / DPW
    bsf = on_path["omega_balls"][w].mean() * DPW / DB * (1 + g) / (2 * math.pi)
    ev = masked_events(on_path, 0.03)
    period = (ev[-1] - ev[0]) / (len(ev) - 1) if len(ev) > 1 else math.inf
    check(len(ev) >= 10 and abs(period * 2 * bsf - 1) < 0.01,
          f"a pit on the contact path: {len(ev)} contacts met, {period * 1e3:.4f} ms apart, "
          f"1 / (2 BSF) = {1e3 / (2 * bsf):.4f} ms at alpha {math.degrees(a):.2f} deg "
          f"({period * 2 * bsf - 1:+.2e})")
    check(np.all(pole["n_masked"] == 0),
          "a pit at the ball's pole (14.5 deg from its rolling axis) is never met")
    # The ball's orientation goes through restart files and across processes: a run split by
    # write_restart/read_restart and a run on 2 processes give the single run's rows.
    case = dict(model="3d", dt=DT, omega=500, Fa=1000, clearance=20e-6, defect="ball", size=20,
                dtrack=14.5, nout=10)
    one, _ = r.run("ball_one", tend=0.008, **case)
    two, _ = r.run("ball_two", tend=0.008, nprocs=2, **case)
    first, _ = r.run("ball_restart_first", deck=os.path.join(os.path.dirname(__file__),
                                                             "in.restart_first"),
                     bearing_deck=r.deck, tend=0.004, **case)
    second, _ = r.run("ball_restart_second", tend=0.008, start="restart",
                      restart_file=os.path.join(first, "half.restart"), **case)
    a = open(os.path.join(one, "signal.txt")).read().splitlines()
    b = open(os.path.join(two, "signal.txt")).read().splitlines()
    rows = open(os.path.join(second, "signal.txt")).read().splitlines()
    masked = sum(float(x.split()[10]) > 0 for x in a[1:])
    check(a == b and len(rows) > 1 and a[-(len(rows) - 1):] == rows[1:] and masked > 0,
          f"the pit on a 3D ball: 1 and 2 processes and a run split by a restart give the same "
          f"{len(a) - 1} rows ({masked} with the pit met)")
    # The planar limit: no clearance, no axial load, a radial one; the pit on the equator
    # meets the contacts as model 2d's ball pit does.
    planar = dict(omega=500, F=2000, defect="ball", size=10, position=0, tend=0.04, nout=10,
                  dt=DT)
    o2, _ = r.run("ball_planar_2d", load="radial", **planar)
    _, _, s3 = run3d(r, "ball_planar_3d", Fr=2000, **planar)
    e2, e3 = masked_events(read_signal(o2), 0.02), masked_events(s3, 0.02)
    p2, p3 = (np.diff(e).mean() if len(e) > 1 else math.inf for e in (e2, e3))
    check(len(e3) >= 6 and abs(len(e3) - len(e2)) <= 1 and abs(p3 / p2 - 1) < 0.01,
          f"planar limit: model 3d meets the pit {len(e3)} times, {p3 * 1e3:.4f} ms apart; "
          f"model 2d {len(e2)} times, {p2 * 1e3:.4f} ms apart ({p3 / p2 - 1:+.1e})")


def test_post_frequencies(r):
    # ohmdem-post takes the contact angle (--contact-angle, as --beta) and a model 3d run's
    # run.json gives it the run's mean angle: Harris' frequencies with cos(alpha) [H, ch. 1]:
    # FTF = fr/2 (1 - d/D cos a), BPFO = Z FTF, BPFI = Z fr/2 (1 + d/D cos a),
    # BSF = D/(2d) fr (1 - (d/D cos a)^2).
    import json
    import subprocess
    post = os.path.join(os.path.dirname(r.exe), "ohmdem-post")

    def frequencies(*args):
        res = subprocess.run([post, "frequencies", *args, "--format", "json"],
                             capture_output=True, text=True)
        return res.returncode, (json.loads(res.stdout) if res.returncode == 0 else res.stderr)

    def harris(z, d, D, a_deg, fr):
        g = d / D * math.cos(math.radians(a_deg))
        return {"ftf_hz": fr / 2 * (1 - g), "bpfo_hz": z * fr / 2 * (1 - g),
                "bpfi_hz": z * fr / 2 * (1 + g), "bsf_hz": D / (2 * d) * fr * (1 - g * g)}

    _, f = frequencies("--bearing", "6205-2RS_JEM", "--rpm", "1797", "--contact-angle", "12")
    ref = harris(9, 0.00794, 0.03904, 12.0, 1797 / 60)
    worst = max(abs(f[k] / v - 1) for k, v in ref.items())
    _, fb = frequencies("--bearing", "6205-2RS_JEM", "--rpm", "1797", "--beta", "12")
    check(worst < 1e-12 and fb == f, f"--contact-angle 12 on the CWRU 6205: Harris' frequencies "
          f"(worst {worst:.1e}), the same as --beta 12")
    rc, err = frequencies("--bearing", "6205-2RS_JEM", "--rpm", "1797", "--beta", "12",
                          "--contact-angle", "12")
    check(rc != 0 and "not both" in err, "--beta and --contact-angle together: refused")
    out, _, sig = run3d(r, "post_frequencies", Fr=0, Fa=1000, clearance=20e-6, omega=500,
                        tend=0.02, nout=100)
    a = 0.5 * (sig["alpha_inner_mean"][-1] + sig["alpha_outer_mean"][-1])
    _, f = frequencies("--metadata", os.path.join(out, "run.json"))
    ref = harris(NB, DB, DPW, a, 500 / (2 * math.pi))
    worst = max(abs(f[k] / v - 1) for k, v in ref.items())
    check(worst < 1e-9 and abs(f["bearing"]["contact_angle_deg"] - a) < 1e-9,
          f"run.json of a model 3d run: the run's contact angle {a:.4f} deg, Harris' frequencies "
          f"(worst {worst:.1e}; BPFO {f['bpfo_hz']:.3f} Hz, planar "
          f"{NB * 500 / (4 * math.pi) * (1 - DB / DPW):.3f})")


def read_local_last(path):
    """The last snapshot of a LIGGGHTS local dump, as rows."""
    lines = open(path).read().splitlines()
    start = max(i for i, s in enumerate(lines) if s.startswith("ITEM: ENTRIES"))
    return np.array([[float(x) for x in s.split()] for s in lines[start + 1:] if s.strip()])


def test_lubricated(r):
    # Each contact's film against Hamrock and Dowson written out here (Hamrock 1994, ch. 22):
    # h_c/Rx = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^(-0.73 k)), U = eta u/(E' Rx),
    # G = alpha E', W = w/(E' Rx^2), with the contact angle's radii: Rx = d (d_m -+ d cos a) /
    # (2 d_m) (Hamrock: - inner, + outer), k = a/b the exact Hertz ellipticity of the contact's
    # curvatures (Harris' F(rho), jones_harris.py; with Ry = f d/(2f - 1) across the groove),
    # u the surfaces' mean speed in pure
    # rolling: (w_i - w_c) rho on the inner race, w_c rho on the outer, rho the contact point's
    # radius, w_c the run's cage speed. The 13 balls under 1000 N axial, alpha ~14.5 deg.
    import json
    omega = 500.0
    out, _, sig = run3d(r, "lubricated", Fr=0, Fa=1000, clearance=20e-6, omega=omega, tend=0.03,
                        nout=100, lubricant="VG68", area="exact", contacts=round(0.03 / DT),
                        dumpraces=round(0.03 / DT))
    meta = json.load(open(os.path.join(out, "run.json")))
    eta, alpha_pv = meta["eta0"], meta["alpha_pv"]
    e_prime = 2e11 / (1 - 0.3**2)
    d = read_dump_last(os.path.join(out, "races.dump"))
    rows = read_local_last(os.path.join(out, "contacts.dump"))
    wc = sig["omega_balls"][sig["time"] > 0.02].mean()
    worst = 0.0
    for side, rc, electrode in (("inner", RCI, -1), ("outer", RCO, 1)):
        s = 1.0 if side == "inner" else -1.0
        a = np.radians(d[f"f_{side}[8]"])
        Q = d[f"f_{side}[1]"]
        rx = DB * (DPW - s * DB * np.cos(a)) / (2 * DPW)
        f = rc / DB
        rho = DPW / 2 - s * DB / 2 * np.cos(a)
        u = (omega - wc) * rho if side == "inner" else wc * rho
        hc = []
        for k in range(NB):
            _, F = jh.race_sums(DB, DPW, f, a[k], side == "inner")
            kap = jh.ellipticity(F)
            U = eta * u[k] / (e_prime * rx[k])
            G, W = alpha_pv * e_prime, Q[k] / (e_prime * rx[k]**2)
            shape = 1 - 0.61 * math.exp(-0.73 * kap)
            hc.append(rx[k] * 2.69 * U**0.67 * G**0.53 * W**-0.067 * shape)
        mine = rows[rows[:, 6] == electrode]
        mine = mine[np.argsort(mine[:, 0])]
        rel = np.max(np.abs(mine[:, 7] / np.array(hc) - 1))
        worst = max(worst, rel)
        print(f"     {side}: alpha {np.degrees(a).mean():.3f} deg, h_c "
              f"{mine[:, 7].mean() * 1e6:.4f} um (Hamrock-Dowson {np.mean(hc) * 1e6:.4f} um), "
              f"worst {rel:.2e}")
    check(worst < 0.01, f"each contact's central film against Hamrock-Dowson with the contact "
          f"angle's radii and pure rolling's speed (worst {worst:.2e}, within 1 %)")
    # The planar limit of the lubricated bearing: model 2d's impedance and films.
    roll = dict(omega=omega, tend=0.03, nout=100, lubricant="VG68", dt=DT)
    o2, _ = r.run("lub_planar_2d", load="radial", F=2000, **roll)
    o3, _ = r.run("lub_planar_3d", model="3d", Fr=2000, **roll)
    s2, s3 = read_signal(o2), read_signal(o3)
    w = s2["time"] > 0.02
    for col in ("Zabs", "Cb", "hmin_inner", "hmin_outer"):
        rel = s3[col][w].mean() / s2[col][w].mean() - 1
        check(abs(rel) < 1e-3, f"planar limit, 500 rad/s: mean {col} {s3[col][w].mean():.6g} vs "
              f"model 2d {s2[col][w].mean():.6g} ({rel:+.1e})")


def test_lubricated_network(r):
    # The general network (closedform no) against the closed form of the same 3D bearing in oil
    # (1000 N axial, 20 um clearance; 300 N radial as well, so that balls leave the inner race
    # and an idle gap is in series): Z to 1e-12, with 1 and 2 processes; ngspice's .ac analysis
    # of the exported netlist against the compute's Z to 1e-9 (lubricated_network_tests.py's
    # reader); the films break down under 100 V at 20 MV/m (the phase goes to 0 and Rb is the dry
    # R) and not under 1 V (the same signal as without breakdown).
    import shutil
    from lubricated_network_tests import ngspice_z
    case = dict(model="3d", dt=DT, Fr=300, Fa=1000, clearance=20e-6, omega=500,
                lubricant="VG68", tend=0.004, nout=100)
    sig = {}
    for n in (1, 2):
        for cf in ("yes", "no"):
            out, _ = r.run(f"lub_{cf}_np{n}", nprocs=n, closedform=cf, **case)
            sig[cf, n] = (out, read_signal(out))
    a, b = sig["yes", 1][1], sig["no", 1][1]
    za = a["Zabs"] * np.exp(1j * a["Zphase"])
    zb = b["Zabs"] * np.exp(1j * b["Zphase"])
    ez = np.max(np.abs(zb - za) / np.abs(za))
    same = all(open(os.path.join(sig[cf, 1][0], "signal.txt")).read() ==
               open(os.path.join(sig[cf, 2][0], "signal.txt")).read() for cf in ("yes", "no"))
    check(ez < 1e-12 and same, f"model 3d in oil: the network's Z is the closed form's "
          f"({ez:.1e}); 1 and 2 processes give the same signal on both paths")
    if shutil.which("ngspice"):
        out, _ = r.run("lub_spice", closedform="no", netlist=1000, **case)
        s = read_signal(out)
        worst = 0.0
        for step in (1000, 2000, 3000, 4000):
            k = int(np.argmin(np.abs(s["time"] - step * DT)))
            z = ngspice_z(os.path.join(out, f"netlist.{step}.cir"), 0.1)
            worst = max(worst, abs(abs(z) / s["Zabs"][k] - 1),
                        abs(np.angle(z) / s["Zphase"][k] - 1))
        check(worst < 1e-9, f"model 3d in oil: ngspice's .ac |Z| and phase are the compute's "
              f"(worst {worst:.1e}, 4 steps)")
    else:
        print("     (ngspice not installed: its check is not run)")
    base = read_signal(r.run("lub_base", **case)[0])
    low_out, _ = r.run("lub_low", excitation=1, breakdown=2e7, **case)
    high = read_signal(r.run("lub_high", excitation=100, breakdown=2e7, **case)[0])
    low = read_signal(low_out)
    steady = high["time"] > 0.002
    unchanged = all(np.array_equal(low[c], base[c]) for c in base)
    check(unchanged and np.all(np.abs(base["Zphase"][steady] + math.pi / 2) < 0.01),
          "model 3d in oil: capacitive, and 1 V under a 20 MV/m breakdown field changes nothing")
    ph = np.abs(high["Zphase"][steady]).max()
    er = np.max(np.abs(high["Rb"][steady] / high["R"][steady] - 1))
    check(ph < 1e-3 and er < 1e-9,
          f"model 3d in oil, 100 V: every film broke (|phase| up to {ph:.1e} rad), Rb is the dry "
          f"R ({er:.1e})")


def test_lubricated_defect(r):
    # A race pit under the lubricated 3D contact: the film over it is model 2d's strip across
    # the raceway (doc/methods/lubricated_contact.md, "Defects"). Under 500 N axial (alpha 13 deg)
    # a 3 deg outer pit 1 mm wide at the groove bottom lies beside the contact path once the
    # axial load has taken up the play: never masked, Cb as steady as the healthy run's;
    # centred on the path it is met (Cb swings). In the planar limit (Fr 2000 N, no clearance)
    # a 1 deg inner pit gives model 2d's impedance: mean |Z| and Cb, and the spread of Cb, as
    # model 2d's (the spread within 3 %: the balls' re-entries differ in detail).
    case = dict(Fr=0, Fa=500, clearance=20e-6, omega=500, lubricant="VG68", tend=0.03, nout=10)
    _, _, healthy = run3d(r, "lub_healthy", **case)
    _, _, beside = run3d(r, "lub_beside", defect="outer", size=3, dwidth=1e-3, **case)
    _, _, on_path = run3d(r, "lub_on_path", defect="outer", size=3, dwidth=1e-3, dtrack=13.0,
                          **case)
    w = healthy["time"] > 0.015
    swing = [np.ptp(x["Cb"][w]) / x["Cb"][w].mean() for x in (healthy, beside, on_path)]
    check(np.all(beside["n_masked"][w] == 0) and swing[1] < 1.5 * swing[0],
          f"model 3d in oil: a pit beside the contact path is never met (Cb within {swing[1]:.2%},"
          f" healthy {swing[0]:.2%})")
    check(swing[2] > 10 * swing[0] and np.all(np.isfinite(on_path["Zabs"])),
          f"model 3d in oil: the same pit on the path swings Cb by {swing[2]:.2%}")
    planar = dict(omega=500, tend=0.03, nout=10, lubricant="VG68", defect="inner", size=1, dt=DT)
    o2, _ = r.run("lub_pit_2d", load="radial", F=2000, **planar)
    o3, _ = r.run("lub_pit_3d", model="3d", Fr=2000, **planar)
    s2, s3 = read_signal(o2), read_signal(o3)
    w = s2["time"] > 0.015
    for col, stat, tol in (("Zabs", np.mean, 1e-3), ("Cb", np.mean, 1e-3), ("Cb", np.std, 0.03)):
        rel = stat(s3[col][w]) / stat(s2[col][w]) - 1
        check(abs(rel) < tol, f"planar limit, a 1 deg inner pit in oil: {stat.__name__} {col} "
              f"{stat(s3[col][w]):.6g} vs model 2d {stat(s2[col][w]):.6g} ({rel:+.1e})")


def test_mpi_restart(r):
    # Combined load, clearance, rolling with friction: 1 and 2 processes give the same signal
    # to the last bit, and a run split by write_restart/read_restart the single run's rows.
    case = dict(model="3d", Fr=1500, Fa=800, clearance=10e-6, omega=500, dt=DT, nout=10)
    one, _ = r.run("mpi_1", tend=0.003, **case)
    two, _ = r.run("mpi_2", tend=0.003, nprocs=2, **case)
    a = open(os.path.join(one, "signal.txt")).read()
    b = open(os.path.join(two, "signal.txt")).read()
    check(a == b and len(a.splitlines()) > 100,
          "model 3d: the signal is identical with 1 and 2 processes")
    first, _ = r.run("restart_first", deck=os.path.join(os.path.dirname(__file__),
                                                        "in.restart_first"),
                     bearing_deck=r.deck, tend=0.0015, **case)
    second, _ = r.run("restart_second", tend=0.003, start="restart",
                      restart_file=os.path.join(first, "half.restart"), **case)
    rows_b = open(os.path.join(second, "signal.txt")).read().splitlines()
    tail = a.splitlines()[-(len(rows_b) - 1):]
    check(len(rows_b) > 1 and tail == rows_b[1:],
          f"model 3d restart: the second half ({len(rows_b) - 1} rows) is identical to the single "
          f"run")
    # A model's restart record is its own: the planar deck resumed from it stops by name
    # (even with the run check told that the change is meant).
    expect_error(r, "restart_other_model", r"restart data is of model 3d", model="2d",
                 start="restart", restart_file=os.path.join(first, "half.restart"),
                 restart_changes="yes", tend=0.003)


if __name__ == "__main__":
    import sys

    if "--dt" in sys.argv:
        k = sys.argv.index("--dt")
        DT = float(sys.argv[k + 1])
        del sys.argv[k:k + 2]
    run_named_test({"static_axial": test_static_axial, "static_combined": test_static_combined,
                    "angular_contact": test_angular_contact, "planar_limit": test_planar_limit,
                    "kinematics": test_kinematics, "stability": test_stability,
                    "errors": test_errors, "mpi_restart": test_mpi_restart,
                    "defect_width": test_defect_width, "ball_defect": test_ball_defect,
                    "post_frequencies": test_post_frequencies, "lubricated": test_lubricated,
                    "lubricated_network": test_lubricated_network,
                    "lubricated_defect": test_lubricated_defect},
                   "ohmdem3d_")

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Deck tests of the 3D bearing's outer ring on its housing (in.bearing, -var model 3d
-var housing K): its centre free in the plane on a spring of stiffness K, the shaft under Fr.

  static            at rest under Fr the housing carries Fr (outer centre Fr / K along +y, Hooke
                    and Newton's third law), and the shaft's displacement relative to the outer
                    ring is the Jones-Harris one of a held ring (jones_harris.py).
  natural_frequency the rings' oscillation on the housing against the linear model of the
                    housing spring, the two rings' masses and each loaded ball between its two
                    Hertz spring-dashpots (stiffness 1.5 Q / delta from Johnson's elliptic
                    solution, tests/lib/contact/make_reference.py), as vibration_tests.py does
                    for the planar ring.
  mpi               1 and 2 processes, and a run split by write_restart/read_restart, give the
                    same signal to the last bit.
  diagnose          ohmdem-post diagnose names an outer pit of a 3D run from R and from the
                    outer ring's acceleration, with the run.json beside the record.

Usage: housing3d_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import math
import os

import numpy as np

import jones_harris as jh
from bearing3d_tests import DB, DPW, E_STAR, NB, RCI, RCO, read_dump_last, run3d
from bearing_tests import BALL_MASS, DEXT, DINN, RB, run_named_test
from deck_checks import check
from vibration_tests import crossing_frequency, damped_modes, dashpot, hertz_stiffness

MRING = 0.15  # the deck's outer ring mass (kg), also the shaft's (Minner defaults to Mring)
DT = 1e-6


def test_static(r):
    Fr, K, Pd = 1000.0, 5e7, 10e-6
    tend = 0.03
    out, log, sig = run3d(r, "static", Fr=Fr, housing=K, Chousing=3000, clearance=Pd, omega=0,
                          mu=0, tend=tend, nout=100, dumpraces=round(tend / DT))
    d = read_dump_last(os.path.join(out, "races.dump"))
    y, x = sig["outer_y"][-1], sig["outer_x"][-1]
    check(abs(y / (Fr / K) - 1) < 1e-3 and abs(x) < 1e-4 * Fr / K,
          f"the housing carries Fr: outer centre ({x * 1e6:.3g}, {y * 1e6:.5f}) um, Fr/K "
          f"{Fr / K * 1e6:.5f} um ({y / (Fr / K) - 1:+.1e})")
    psi = np.arctan2(d["y"] - y, d["x"] - x)  # each ball's place about the outer ring's centre
    b = jh.Bearing(NB, DB, DPW, RCI, RCO, E_STAR, clearance=Pd)
    q, (Q, _, _, _, _), _ = jh.solve(b, psi, [0, Fr, 0])
    dr = sig["delta_r"][-1]
    worst = np.max(np.abs(d["f_inner[1]"] - Q)) / Q.max()
    check(abs(dr / q[1] - 1) < 0.01 and worst < 0.01,
          f"relative to the outer ring: delta_r {dr * 1e6:.4f} um (Jones-Harris {q[1] * 1e6:.4f}),"
          f" ball loads within {worst:.1e} of Qmax {Q.max():.1f} N")
    moving = np.abs(sig["vel_along"][: len(sig["time"]) // 10])
    check(np.all(np.isfinite(sig["acc_along"])) and moving.max() > 0,
          f"the vibration channel moves on the housing (|vel_along| up to {moving.max():.3g} m/s)")


def test_natural_frequency(r):
    # Light damping on both rings and a 40 um clearance against +-10 um of common motion, so
    # that the balls outside the load zone mostly keep off the rings through the swing (those
    # beside it touch at times, which the linear model leaves out). The linear model: dofs
    # y_o (outer ring, +y), y_i (shaft, +y) and r_j (loaded ball j, outward); ball j at
    # c_j = cos(angle from +y): outer compression r_j - c_j y_o, inner c_j y_i - r_j; the
    # housing K y_o^2 / 2.
    Fr, K, C, Pd = 500.0, 5e7, 20.0, 40e-6
    tend = 0.008
    out, _, sig = run3d(r, "natural", Fr=Fr, housing=K, Chousing=C, Cinner=C, clearance=Pd,
                        omega=0, mu=0, tend=tend, nout=1, dumpraces=round(tend / DT))
    d = read_dump_last(os.path.join(out, "races.dump"))
    q_out, q_in = d["f_outer[1]"], d["f_inner[1]"]
    loaded = (q_out > 1e-3 * Fr / NB) & (q_in > 1e-3 * Fr / NB)
    ox, oy = sig["outer_x"][-1], sig["outer_y"][-1]
    c = (d["y"][loaded] - oy) / np.hypot(d["x"][loaded] - ox, d["y"][loaded] - oy)
    k_o = np.array([hertz_stiffness(q, 1 / RB - 2 / DEXT, 1 / RB - 1 / RCO) for q in q_out[loaded]])
    k_i = np.array([hertz_stiffness(q, 1 / RB + 2 / DINN, 1 / RB - 1 / RCI) for q in q_in[loaded]])
    nl = int(loaded.sum())

    def assemble(ko, ki, ring_o, ring_i):
        A = np.zeros((nl + 2, nl + 2))
        A[0, 0] = ring_o + np.sum(ko * c * c)
        A[1, 1] = ring_i + np.sum(ki * c * c)
        for j in range(nl):
            A[0, j + 2] = A[j + 2, 0] = -ko[j] * c[j]
            A[1, j + 2] = A[j + 2, 1] = -ki[j] * c[j]
            A[j + 2, j + 2] = ko[j] + ki[j]
        return A

    Kmat = assemble(k_o, k_i, K, 0.0)
    Dmat = assemble(np.array([dashpot(k) for k in k_o]), np.array([dashpot(k) for k in k_i]), C, C)
    s_eig, modes = damped_modes(np.diag([MRING, MRING] + [BALL_MASS] * nl), Kmat, Dmat)
    up = s_eig.imag > 0
    f_modes = np.sort(s_eig.imag[up]) / (2 * math.pi)
    f_model = f_modes[0]  # the rings swinging together on the housing
    f_rigid = math.sqrt(K / (2 * MRING + nl * BALL_MASS)) / (2 * math.pi)
    keep = sig["time"] > 0.002  # the bearing's own modes, damped by the contacts, have died out
    v = sig["vel_along"][keep]
    f_sim, nz = crossing_frequency(sig["time"][keep], v - np.mean(v))
    contacts = sig["n_contacts_race"][keep]
    print(f"loaded balls {nl}, loads {np.round(q_out[loaded], 1)} N; race contacts "
          f"{int(contacts.min())}..{int(contacts.max())} in the window (the model's {2 * nl}); "
          f"the model's modes "
          f"{np.round(f_modes[:3], 1)} Hz; rigid bearing on the housing {f_rigid:.1f} Hz")
    check(nz >= 8 and abs(f_sim / f_model - 1) < 0.01,
          f"outer ring on its housing: {f_sim:.1f} Hz ({nz} zero crossings) vs the Hertz "
          f"spring-dashpot model {f_model:.1f} Hz ({f_sim / f_model - 1:+.2%})")


def test_mpi(r):
    case = dict(model="3d", dt=DT, Fr=1500, Fa=300, clearance=10e-6, omega=500, housing=5e7,
                nout=10)
    one, _ = r.run("mpi_1", tend=0.002, **case)
    two, _ = r.run("mpi_2", tend=0.002, nprocs=2, **case)
    a = open(os.path.join(one, "signal.txt")).read().splitlines()
    b = open(os.path.join(two, "signal.txt")).read().splitlines()
    first, _ = r.run("restart_first", deck=os.path.join(os.path.dirname(__file__),
                                                        "in.restart_first"),
                     bearing_deck=r.deck, tend=0.001, **case)
    second, _ = r.run("restart_second", tend=0.002, start="restart",
                      restart_file=os.path.join(first, "half.restart"), **case)
    rows = open(os.path.join(second, "signal.txt")).read().splitlines()
    check(a == b and len(a) > 100 and len(rows) > 1 and a[-(len(rows) - 1):] == rows[1:],
          f"model 3d on a housing: 1 and 2 processes and a run split by a restart give the same "
          f"{len(a) - 1} rows")


def test_diagnose(r):
    # As a user runs it: a 1 deg outer pit in the load zone (+y, position 90) of the 3D bearing
    # under Fr 1000 N and Fa 300 N on its housing; `ohmdem-post diagnose` with the run.json
    # beside the record (its "load": "shaft" read as the radial load it is) names the outer race
    # from R and from the housing's acceleration.
    import subprocess
    post = os.path.join(os.path.dirname(r.exe), "ohmdem-post")
    out, _, _ = run3d(r, "diagnose", Fr=1000, Fa=300, clearance=10e-6, housing=5e7,
                      defect="outer", size=1, position=90, tend=0.2, nout=10)
    for column in ("R", "acc_along"):
        res = subprocess.run([post, "diagnose", os.path.join(out, "signal.txt"), "--column",
                              column], capture_output=True, text=True)
        verdict = [l for l in res.stdout.splitlines() if l.startswith("defect:")]
        check(res.returncode == 0 and verdict and verdict[0].split()[1] == "outer",
              f"diagnose --column {column} of a model 3d run on its housing: "
              f"{verdict[0] if verdict else res.stderr.strip()[-200:]}")
    # The model data of a size are the planar scene's: `model` refuses the 3D record by name.
    res = subprocess.run([post, "model", os.path.join(out, "signal.txt")], capture_output=True,
                         text=True)
    check(res.returncode != 0 and "is a model 3d run's" in res.stderr,
          f"model refuses a model 3d record: {res.stderr.strip()[-160:]}")


if __name__ == "__main__":
    run_named_test({"static": test_static, "natural_frequency": test_natural_frequency,
                    "mpi": test_mpi, "diagnose": test_diagnose}, "ohmdem_housing_")

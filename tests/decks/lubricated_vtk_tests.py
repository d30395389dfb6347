# SPDX-License-Identifier: GPL-2.0-or-later
"""Deck-level tests of the lubricated 6208's VTK export (compute network/resistance with a
lubricant and `vtk`, doc/compute_network_resistance.md): the companion file
network_lubricated.STEP.vtk read back and held against the same run's signal.txt:
  vtk      one point per ball-race contact on the race's surface; lambda = h_min / sigma;
           the films' minimum the signal's hmin_inner/outer; the balls' series capacitances
           sum to Cb; the high race's current phasors sum to the injected current
           (Kirchhoff); listed in the .pvd as part 3; without a lubricant no such file.
  vtk_mpi  the files are identical with 1 and 2 processes.
Run through lubricated_network_tests.py (vtk, vtk_mpi).
"""
import glob
import json
import os

import numpy as np

from bearing_tests import read_signal
from deck_checks import check

TEND, DT, EVERY = 0.003, 1e-5, 100
RINN, REXT = 0.024, 0.0366  # the 6208's race radii (the deck's default, the paper's Table 1)
NAMES = ["ball", "race", "h_central", "h_min", "lambda", "C", "G", "current_abs",
         "current_phase", "loaded"]


def read_points_vtk(path):
    """The POINTS and the POINT_DATA scalars of a legacy ASCII VTK POLYDATA file."""
    words = open(path).read().split()
    k = words.index("POINTS")
    n = int(words[k + 1])
    pts = np.array(words[k + 3:k + 3 + 3 * n], float).reshape(n, 3)
    data = {}
    k = words.index("POINT_DATA")
    while True:
        try:
            k = words.index("SCALARS", k + 1)
        except ValueError:
            break
        data[words[k + 1]] = np.array(words[k + 6:k + 6 + n], float)  # after LOOKUP_TABLE default
    check(words[words.index("VERTICES") + 1] == str(n), f"{os.path.basename(path)}: a vertex per point")
    return pts, data


def lubricated_files(out):
    return sorted(glob.glob(os.path.join(out, "vtk", "network_lubricated.*.vtk")),
                  key=lambda f: int(f.split(".")[-2]))


def test_vtk(r):
    out, _ = r.run("vtk", lubricant="VG68", tend=TEND, dt=DT, nout=10, vtk=EVERY)
    sig, meta = read_signal(out), json.load(open(os.path.join(out, "run.json")))
    files = lubricated_files(out)
    check(len(files) == 4, f"a lubricated contacts file at steps 0, 100, 200, 300 ({len(files)})")
    pvd = open(os.path.join(out, "vtk", "network.pvd")).read()
    check('part="3" file="network_lubricated.300.vtk"' in pvd, "the .pvd lists it as part 3")
    omega = 2 * np.pi * meta["fexc"]
    compared = 0
    for f in files:
        step = int(f.split(".")[-2])
        pts, d = read_points_vtk(f)
        check(sorted(d) == sorted(NAMES), f"step {step}: point data {sorted(d)}")
        nb = len(np.unique(d["ball"]))
        check(len(pts) == 2 * nb and np.all(np.bincount(d["race"].astype(int)) == nb),
              f"step {step}: two contacts per ball ({nb} balls), one on each race")
        # High electrode = outer race (the deck's `high race outer`): its points on the
        # outer groove, the others on the inner one (to the films' and the Hertz deflection).
        rad = np.hypot(pts[:, 0], pts[:, 1])
        out_r, in_r = rad[d["race"] == 0], rad[d["race"] == 1]
        check(np.all(np.abs(out_r - REXT) < 2e-5) and np.all(np.abs(in_r - RINN) < 2e-5),
              f"step {step}: points on the races (|r - R| <= {max(abs(out_r - REXT).max(), abs(in_r - RINN).max()):.1e} m)")
        loaded = d["loaded"] == 1
        check(np.allclose(d["lambda"][loaded], d["h_min"][loaded] / meta["roughness"], rtol=1e-12),
              f"step {step}: lambda = h_min / sigma")
        k = int(np.argmin(np.abs(sig["time"] - step * DT)))
        if abs(sig["time"][k] - step * DT) > DT / 2:
            continue  # step 0: signal.txt starts at its first period
        compared += 1
        for col, race in (("hmin_inner", 1), ("hmin_outer", 0)):
            m = loaded & (d["race"] == race)
            if m.any():
                check(abs(d["h_min"][m].min() / sig[col][k] - 1) < 1e-12,
                      f"step {step}: the smallest loaded film on race {race} is {col}")
        # Each ball: its two contacts in series (y = G + j omega C); the balls in parallel.
        y = d["G"] + 1j * omega * d["C"]
        ball_y = 0
        for b in np.unique(d["ball"]):
            y1, y2 = y[d["ball"] == b]
            ball_y += y1 * y2 / (y1 + y2)
        check(abs(ball_y.imag / omega / sig["Cb"][k] - 1) < 1e-9,
              f"step {step}: the contacts' C and G give Cb ({ball_y.imag / omega:.6e} F)")
        i_high = d["current_abs"] * np.exp(1j * d["current_phase"])
        total = i_high[d["race"] == 0].sum()
        check(abs(total - 0.1) < 1e-9 * 0.1,
              f"step {step}: the currents into the balls at the high race sum to I = 0.1 A "
              f"({total.real:.15f}{total.imag:+.1e}j)")
        check(np.allclose(i_high[d["race"] == 1].sum(), -total, rtol=1e-12),
              f"step {step}: and leave them at the low race")
    check(compared == 3, "three steps compared with signal.txt")
    dry, _ = r.run("dry", tend=TEND, dt=DT, nout=10, vtk=EVERY)
    check(not lubricated_files(dry) and 'part="3"' not in open(os.path.join(dry, "vtk", "network.pvd")).read(),
          "without a lubricant: no lubricated file, the .pvd as before")


def test_vtk_mpi(r):
    texts = []
    for nprocs in (1, 2):
        out, _ = r.run(f"np{nprocs}", lubricant="VG68", load="radial", tend=TEND, dt=DT, nout=10,
                       vtk=EVERY, nprocs=nprocs)
        texts.append([open(f).read() for f in lubricated_files(out)])
    check(len(texts[0]) == 4 and texts[0] == texts[1],
          "the lubricated contacts files are identical with 1 and 2 processes")


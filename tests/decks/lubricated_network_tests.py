#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Deck-level tests of the lubricated 6208's general network and AC netlist (compute
network/resistance with a lubricant, doc/methods/lubricated_contact.md "The network"):
  network  the complex network solve (closedform no) against the closed form (closedform yes),
           to 1e-12, with 1 and 2 processes; the per-contact local array's lubricated columns.
  ngspice  the exported AC netlist run by ngspice's .ac analysis (its own sparse LU on the
           MNA system, its own parsing of every R and C): |Z| and phase against the compute's
           to 1e-9, with 1 and 2 processes (exit 77, a ctest skip, without ngspice).
  vtk, vtk_mpi  the lubricated contacts' VTK file (lubricated_vtk_tests.py).
Usage: lubricated_network_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import cmath
import glob
import json
import math
import os
import shutil
import subprocess
import sys

import numpy as np

from bearing_tests import read_signal, run_named_test
from deck_checks import check
from lubricated_vtk_tests import test_vtk, test_vtk_mpi

TEND, DT = 0.003, 1e-5
Z_COLUMNS = ["Zabs", "Zphase", "Cb", "Rb"]


def z_of(sig, k):
    return cmath.rect(sig["Zabs"][k], sig["Zphase"][k])


def compare_paths(r, name, nprocs, **var):
    cf, _ = r.run(f"{name}_cf_np{nprocs}", lubricant=var.pop("lubricant", "VG68"), tend=TEND,
                  dt=DT, nout=10, nprocs=nprocs, closedform="yes", **var)
    var.pop("closedform", None)
    net, _ = r.run(f"{name}_net_np{nprocs}", lubricant=json.load(
        open(os.path.join(cf, "run.json")))["lubricant"], tend=TEND, dt=DT, nout=10,
        nprocs=nprocs, closedform="no", **var)
    a, b = read_signal(cf), read_signal(net)
    # Z as a complex number (the phase of an ohmic bearing is ~1e-5: compared through Z, and
    # Cb, Rb through Y = 1/Z in units of |Y|).
    ez = max(abs(z_of(b, k) - z_of(a, k)) / abs(z_of(a, k)) for k in range(len(a["time"])))
    ya = [1 / z_of(a, k) for k in range(len(a["time"]))]
    w = 2 * math.pi * json.load(open(os.path.join(cf, "run.json")))["fexc"]
    ey = max(max(abs(b["Cb"][k] - a["Cb"][k]) * w, abs(1 / b["Rb"][k] - 1 / a["Rb"][k])) / abs(y)
             for k, y in enumerate(ya))
    print(f"     {name}, {nprocs} process(es): |dZ|/|Z| {ez:.2e}, Cb and 1/Rb {ey:.2e} of |Y|")
    check(ez < 1e-12, f"{name} np{nprocs}: the network's Z is the closed form's to 1e-12")
    check(ey < 1e-12, f"{name} np{nprocs}: the network's Cb and Rb are the closed form's")
    # The dry R follows closedform too (the general DC network): equal to rounding.
    er = np.max(np.abs(b["R"] / a["R"] - 1))
    check(er < 1e-12, f"{name} np{nprocs}: the dry R of both paths agree ({er:.1e})")
    rest = [c for c in a if c not in Z_COLUMNS + ["R"]]
    check(all(np.array_equal(a[c], b[c]) for c in rest),
          f"{name} np{nprocs}: every other column identical")
    meta = json.load(open(os.path.join(net, "run.json")))
    check(meta.get("impedance") == "network", "run.json: impedance network")
    check(json.load(open(os.path.join(cf, "run.json"))).get("impedance") == "closedform",
          "run.json: impedance closedform")
    return net


def test_network(r):
    nets = [compare_paths(r, "vg68", n) for n in (1, 2)]
    s = [open(os.path.join(n, "signal.txt")).read() for n in nets]
    check(s[0] == s[1], "network: signal.txt identical with 1 and 2 processes")
    # A radial load (balls touching one race: an idle gap in series) and the ohmic regime.
    compare_paths(r, "radial", 1, load="radial")
    compare_paths(r, "ohmic", 1, lubricant="VG32", temperature=100, omega=30)
    # The local array: each ball's two contacts, the current phasor into the ball at the
    # high race and out at the low one, the balls' real parts summing to I.
    out, _ = r.run("local", lubricant="VG68", tend=TEND, dt=DT, nout=10, contacts=300,
                   closedform="no")
    rows = read_last_dump(os.path.join(out, "contacts.dump"))
    check(rows.shape[1] == 14, f"local array: 14 columns with a lubricant ({rows.shape[1]})")
    balls = sorted(set(rows[:, 0]))
    check(rows.shape[0] == 2 * len(balls), "local array: two rows per ball")
    hi, lo = rows[rows[:, 6] == 1], rows[rows[:, 6] == -1]
    i_total = complex(hi[:, 12].sum(), hi[:, 13].sum())
    check(abs(i_total - 0.1) < 1e-12, f"local array: the currents into the high race sum to I "
          f"({i_total.real:.15f}{i_total.imag:+.1e}j)")
    check(np.array_equal(hi[:, 12], -lo[:, 12]), "local array: what enters a ball leaves it")
    # Columns 7-13: h_central, h_min, lambda, C, G, Re I, Im I. Every contact is pressed
    # under the deck's isotropic load (a film: G > 0 from the oil's leakage).
    sig = read_signal(out)
    check(np.all(rows[:, 11] > 0), "local array: every contact pressed (G > 0)")
    check(rows[:, 9].min() == sig["lambda_min"][-1], "local array: the smallest lambda is lambda_min")
    check(np.all(rows[:, 10] > 0) and np.all(rows[:, 8] < rows[:, 7]),
          "local array: C > 0 and h_min < h_central")


def read_last_dump(path):
    lines = open(path).read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ENTRIES"))
    return np.array([[float(x) for x in l.split()] for l in lines[start + 1:] if l.strip()])


def ngspice_z(cir, current):
    raw = cir[:-4] + ".raw"
    env = dict(os.environ, SPICE_ASCIIRAWFILE="1")  # 16 digits (the listing has 6)
    res = subprocess.run(["ngspice", "-b", "-r", raw, cir], capture_output=True, text=True,
                         env=env, cwd=os.path.dirname(cir))
    text = res.stdout + res.stderr
    if res.returncode != 0 or "singular" in text or "rror" in text:
        sys.exit(f"FAIL: ngspice on {cir}: rc {res.returncode}\n{text[-2000:]}")
    head, values = open(raw).read().split("Values:")
    names = [l.split()[1] for l in head.splitlines() if l.startswith("\t")]
    vals = values.split()[1:]  # the point index, then one value per variable
    v = complex(*map(float, vals[names.index("v(ehigh)")].split(",")))
    return v / current


def test_ngspice(r):
    if shutil.which("ngspice") is None:
        print("SKIP: ngspice is not installed (apt-get install ngspice; CI installs it)")
        sys.exit(77)
    texts = []
    for nprocs in (1, 2):
        out, _ = r.run(f"spice_np{nprocs}", lubricant="VG68", load="radial", tend=TEND, dt=DT,
                       nout=10, netlist=100, nprocs=nprocs)
        sig = read_signal(out)
        files = sorted(glob.glob(os.path.join(out, "netlist.*.cir")),
                       key=lambda f: int(f.split(".")[-2]))
        check(len(files) == 4, f"np{nprocs}: a netlist at steps 0, 100, 200, 300")
        texts.append([open(f).read() for f in files])
        worst, compared = 0.0, 0
        for f in files:
            step = int(f.split(".")[-2])
            k = int(np.argmin(np.abs(sig["time"] - step * DT)))
            z = ngspice_z(f, 0.1)  # every file runs (step 0: capacitors only, rshunt's DC path)
            if abs(sig["time"][k] - step * DT) > DT / 2:
                continue  # step 0: signal.txt starts at its first period
            compared += 1
            ea = abs(abs(z) / sig["Zabs"][k] - 1)
            ep = abs(cmath.phase(z) / sig["Zphase"][k] - 1)
            print(f"     step {step}: ngspice |Z| {abs(z):.15e} phase {cmath.phase(z):.15f}, "
                  f"compute {sig['Zabs'][k]:.15e} {sig['Zphase'][k]:.15f}")
            worst = max(worst, ea, ep)
        print(f"     np{nprocs}: worst relative difference of |Z| and phase to ngspice {worst:.2e}")
        check(compared == 3 and worst < 1e-9,
              f"np{nprocs}: ngspice's .ac |Z| and phase are the compute's to 1e-9 ({compared} steps)")
    check(texts[0] == texts[1], "the netlists are identical with 1 and 2 processes")
    check(".ac lin 1 10000 10000" in texts[0][-1] and "I1 0 ehigh AC 0.1" in texts[0][-1],
          "the netlist's .ac card and AC source")


if __name__ == "__main__":
    run_named_test({"network": test_network, "ngspice": test_ngspice, "vtk": test_vtk,
                    "vtk_mpi": test_vtk_mpi}, "ohmdem_lubnet_")

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""compute network/resistance's local array (per-contact rows) on the bearing deck and the
validation packing, checked by kirchhoff_check.py (numpy, independent of the C++): Kirchhoff
at every particle, the electrodes carrying I, Ohm on every row; the bearing's rows against R
from signal.txt, the closed form against the general network, 1 against 2 MPI processes.
Usage: contact_output_tests.py TEST --exe OHMDEM --src SOURCE_DIR"""
import argparse
import os
import re
import tempfile

import numpy as np

from deck_checks import check, finish, read_signal
from kirchhoff_check import check_dump
import validation_tests

I = 0.1  # the decks' injected current (A): in.bearing and in.packing, variable I


def run(exe, deck, out, nprocs=1, **var):
    validation_tests.run(exe, deck, out, nprocs, **var)  # stops the test on a failed run
    return out


def sorted_rows(rows):
    return rows[np.lexsort((rows[:, 3], rows[:, 2], -rows[:, 6], rows[:, 1], rows[:, 0]))]


def same_rows(a, b, rtol, what):
    ok = a.keys() == b.keys()
    worst = 0.0
    for step in a if ok else []:
        x, y = sorted_rows(a[step]), sorted_rows(b[step])
        if x.shape != y.shape or np.any(x[:, [0, 1, 5, 6]] != y[:, [0, 1, 5, 6]]):
            ok = False
            break
        scale = np.maximum(np.abs(x[:, 2:5]).max(axis=0), 1e-300)
        worst = max(worst, float(np.max(np.abs(x[:, 2:5] - y[:, 2:5]) / scale, initial=0.0)))
    check(ok and worst <= rtol, f"{what}: same rows (largest difference {worst:.3g} of a "
          f"column's scale, allowed {rtol:g})")


def bearing(r, name, nprocs=1, **var):
    base = dict(tend=0.003, dt=1e-5, contacts=20, here=os.path.join(r.src, "inputs",
                "bearing_6208"), catalog=os.path.join(r.src, "inputs", "bearings"))
    base.update(var)
    deck = os.path.join(r.src, "inputs", "bearing_6208", "in.bearing")
    out = run(r.exe, deck, os.path.join(r.wd, name), nprocs, **base)
    steps, worst = check_dump(os.path.join(out, "contacts.dump"), I)
    check(True, f"bearing {name}: Kirchhoff and Ohm on {len(steps)} steps of contacts.dump "
          f"(worst {worst:.2g} of I)")
    return out, steps


def packing(r, name, nprocs=1, **var):
    deck = os.path.join(r.src, "inputs", "validation", "in.packing")
    out = run(r.exe, deck, os.path.join(r.wd, name), nprocs, contacts=1, **var)
    steps, worst = check_dump(os.path.join(out, "contacts.dump"), I)
    n = max(len(s) for s in steps.values())
    check(True, f"packing {name}: Kirchhoff and Ohm, {n} contact rows (worst {worst:.2g} of I)")
    return out, steps


def test_bearing(r):
    out, steps = bearing(r, "closed_form")
    sig = read_signal(os.path.join(out, "signal.txt"))
    # Eq. 1 only: each ball is one resistor between the races, its high contact row carries
    # the whole drop R I (R from signal.txt, the compute's scalar).
    worst, n = 0.0, 0
    for step, rows in steps.items():
        t = step * 1e-5
        k = np.argmin(np.abs(np.asarray(sig["time"]) - t))
        if step == 0 or abs(sig["time"][k] - t) > 1e-12:
            continue
        v = sig["R"][k] * I
        high = rows[(rows[:, 6] == 1) & (rows[:, 3] != 0)]
        if len(high):
            worst = max(worst, float(np.max(np.abs(high[:, 4] - v)) / v))
            n += 1
    check(n > 0 and worst < 1e-9, f"bearing: the drop across each conducting ball is R I "
          f"({n} steps, worst {worst:.2g})")
    _, general = bearing(r, "general", closedform="no")
    same_rows(steps, general, 1e-9, "bearing eq1: closed form and general network")


def test_bearing_holm(r):
    _, closed = bearing(r, "holm_closed", emodel="eq1+holm")
    _, general = bearing(r, "holm_general", emodel="eq1+holm", closedform="no")
    same_rows(closed, general, 1e-9, "bearing eq1+holm: closed form and general network")


def test_bearing_defect(r):
    # A 60 degree zone of the outer race: some contacts lie in it (masked, no current).
    _, steps = bearing(r, "defect", defect="outer", size=60.0)
    masked = sum(int(np.sum(s[:, 5])) for s in steps.values())
    check(masked > 0, f"bearing with an outer-race defect: {masked} masked contact rows")


def test_packing(r):
    for model in ("eq1", "eq1+holm"):
        packing(r, model.replace("+", "_"), model=model)
    # Holm only: every conductance of the network is one contact's row, so by Tellegen's
    # theorem the power of the rows, sum(current * drop), is the power R I^2 the source
    # delivers, with R the compute's own (the log's PACKING_R).
    out, steps = packing(r, "holm", model="holm")
    log = open(os.path.join(out, "log.txt")).read()
    R = float(re.findall(r"^PACKING_R (\S+)", log, re.M)[-1])
    rows = steps[max(steps)]
    power = float(np.sum(rows[:, 3] * rows[:, 4]))
    check(abs(power / (R * I * I) - 1.0) < 1e-9, f"packing holm: power of the rows {power!r} W "
          f"= R I^2 = {R * I * I!r} W (R = {R!r} ohm from the compute)")


def by_position(out, steps):
    """The rows with atom IDs replaced by each particle's rank in position order: create_atoms
    numbers the particles differently on 1 and 2 processes."""
    lines = open(os.path.join(out, "particles.dump")).read().split("ITEM: ATOMS")[1]
    p = np.array([list(map(float, l.split())) for l in lines.strip().split("\n")[1:]])
    order = np.lexsort((p[:, 3], p[:, 2], p[:, 1]))
    new_id = {int(p[k, 0]): n + 1 for n, k in enumerate(order)}
    mapped = {}
    for step, rows in steps.items():
        rows = rows.copy()
        for k in range(len(rows)):
            rows[k, 0], rows[k, 1] = new_id[int(rows[k, 0])], new_id.get(int(rows[k, 1]), 0)
        mapped[step] = rows
    return mapped


def test_reduce(r):
    # compute network/contacts forwards the local array to compute reduce (which reads a
    # compute's per-atom output whenever it has one): max and sum of the current column
    # against the dump's.
    deck = open(os.path.join(r.src, "inputs", "validation", "in.packing")).read()
    extra = ("compute C all network/contacts R\ncompute Imax all reduce max c_C[4]\n"
             "compute Isum all reduce sum c_C[4]\n")
    deck = re.sub(r"^thermo_style( +custom[^\n]*c_R[^\n]*)", lambda m: extra + "thermo_style" + m.group(1) +
                  " c_Imax c_Isum", deck, count=1, flags=re.M)
    deck += '\nvariable imax equal c_Imax\nvariable isum equal c_Isum\n' \
            'print "REDUCE ${imax} ${isum}"\n'
    path = os.path.join(r.wd, "in.packing_reduce")
    open(path, "w").write(deck)
    out = run(r.exe, path, os.path.join(r.wd, "reduce"), contacts=1, cells=3)
    steps, _ = check_dump(os.path.join(out, "contacts.dump"), I)
    last = steps[max(steps)]
    got = [float(x) for x in re.findall(r"^REDUCE (\S+) (\S+)",
                                        open(os.path.join(out, "log.txt")).read(), re.M)[-1]]
    want = [last[:, 3].max(), last[:, 3].sum()]
    check(np.allclose(got, want, rtol=1e-13, atol=0),
          f"compute reduce max/sum of the current column {got} = the dump's {want}")


def test_mpi(r):
    # Holm only: particles are equipotential, a row's element is the contact's constriction,
    # the same whichever particle has the smaller ID.
    out1, a = packing(r, "mpi_1", model="holm")
    out2, b = packing(r, "mpi_2", nprocs=2, model="holm")
    a, b = by_position(out1, a), by_position(out2, b)
    for rows in (a, b):
        for step in rows:
            swap = (rows[step][:, 1] != 0) & (rows[step][:, 1] < rows[step][:, 0])
            rows[step][swap] = rows[step][swap][:, [1, 0, 2, 3, 4, 5, 6]] * [1, 1, 1, -1, -1, 1, 1]
    same_rows(a, b, 1e-12, "packing: 1 and 2 MPI processes (particles matched by position)")
    _, a = bearing(r, "mpi_1")
    _, b = bearing(r, "mpi_2", nprocs=2)
    same_rows(a, b, 0.0, "bearing: 1 and 2 MPI processes")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("test", choices=["bearing", "bearing_holm", "bearing_defect", "packing",
                                     "reduce", "mpi"])
    ap.add_argument("--exe", required=True)
    ap.add_argument("--src", required=True)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="contacts_") as wd:
        r = argparse.Namespace(exe=os.path.abspath(a.exe), src=os.path.abspath(a.src), wd=wd)
        globals()["test_" + a.test](r)
    finish()


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Validation of compute network/resistance on the decks of inputs/validation/.

chain: R against the closed-form series sum of eq. 1 resistors, computed here from the sphere
positions with Hertz theory (independent of our C++). packing: R against ngspice run on the
netlist the compute exports. Usage:
  validation_tests.py TEST --exe OHMDEM --src SOURCE_DIR [--ngspice-cache DIR]
"""
import argparse
import hashlib
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

from deck_checks import check, finish

def run(exe, deck, out, nprocs=1, **var):
    os.makedirs(out, exist_ok=True)
    cmd = [exe, "-in", deck, "-log", os.path.join(out, "log.txt"), "-screen", "none",
           "-var", "out", out]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    if nprocs > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
    res = subprocess.run(cmd, cwd=out, capture_output=True, text=True)
    log = open(os.path.join(out, "log.txt")).read()
    if res.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)}\n{res.stdout[-2000:]}{res.stderr[-2000:]}{log[-2000:]}")
    return log


def last_dump_rows(dump):
    """(id, value) rows of the last snapshot of a two-column custom dump."""
    with open(dump) as f:
        lines = f.read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    return [(int(l.split()[0]), float(l.split()[1])) for l in lines[start + 1:]]


def chain_reference(dump, gamma, E=2e11, nu=0.3, model="eq1", areas_out=None):
    """Closed form of the chain from the sphere positions (Hertz): the series sum of the eq. 1
    resistors of the inner spheres and/or of the Holm constrictions rho/(2a) of the contacts."""
    rows = []
    with open(dump) as f:
        lines = f.read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    for l in lines[start + 1:]:
        rows.append([float(w) for w in l.split()])
    rows = np.array(sorted(rows))
    z, r = rows[:, 1], rows[:, 2]
    e_star = 1 / (2 * (1 - nu**2) / E)
    areas = []
    for k in range(len(z) - 1):
        delta = r[k] + r[k + 1] - (z[k + 1] - z[k])
        if delta <= 0:
            return math.inf
        rstar = r[k] * r[k + 1] / (r[k] + r[k + 1])
        fn = 4 / 3 * e_star * math.sqrt(rstar) * delta**1.5  # LIGGGHTS hertz, at rest
        c = (3 * fn * rstar / (4 * e_star)) ** (1 / 3)         # paper eq. 2 (sphere: r_eff = R*)
        areas.append(math.pi * c * c)
    if areas_out is not None:
        areas_out.extend(areas)
    total = 0.0
    if model in ("eq1", "eq1+holm"):
        for k in range(1, len(z) - 1):  # inner spheres: contacts k-1 and k face each other
            V = 4 / 3 * math.pi * r[k] ** 3
            total += 1 / (gamma * areas[k - 1] * areas[k] / (2 * V * (1 - math.cos(math.pi))))
    if model in ("holm", "eq1+holm"):  # Holm (1967): rho/(2a) for a circular spot
        total += sum(1 / gamma / (2 * math.sqrt(S / math.pi)) for S in areas)
    return total


def read_local(path):
    rows, take = [], False
    for l in open(path).read().splitlines():
        if l.startswith("ITEM: ENTRIES"):
            rows, take = [], True
        elif l.startswith("ITEM:"):
            take = False
        elif take and l.strip():
            rows.append([float(w) for w in l.split()])
    return np.array(rows)


def areas_ref_10(wd):
    areas = []
    chain_reference(os.path.join(wd, "chain10_eq1", "atoms.dump"), 5.88e7, areas_out=areas)
    return areas


def read_R(log, key):
    return float(re.search(rf"^{key} (\S+)", log, re.M).group(1))


def thermo_R(log):
    """R of every thermo row of the last run, as printed (17 digits: every bit)."""
    block = log[log.rindex("Step"):]
    block = block[:block.index("Loop time")]
    return [row.split()[2] for row in block.splitlines()[1:] if row.strip()]


NGSPICE_CACHE = None  # --ngspice-cache DIR


def ngspice_R(cir, current):
    """ngspice's R of a netlist (its high node's potential over the current). ngspice's LU
    takes ~10 s on the packing's 20 000 conductances, and four tests export the same two
    netlists (bit for bit: the same deck and seed), so with --ngspice-cache its answer is kept
    under the netlist's SHA-256: a netlist that differs in any byte is solved again."""
    if NGSPICE_CACHE:
        key = hashlib.sha256(open(cir, "rb").read() + repr(current).encode()).hexdigest()
        kept = os.path.join(NGSPICE_CACHE, key)
        if os.path.isfile(kept):
            return float(open(kept).read())
    R = ngspice_run(cir, current)
    if NGSPICE_CACHE:
        os.makedirs(NGSPICE_CACHE, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=NGSPICE_CACHE)
        with os.fdopen(fd, "w") as f:
            f.write(repr(R))
        os.replace(tmp, kept)  # whole or absent: tests run side by side
    return R


def ngspice_run(cir, current):
    raw = cir + ".raw"
    env = dict(os.environ, SPICE_ASCIIRAWFILE="1")
    res = subprocess.run(["ngspice", "-b", "-r", raw, cir], capture_output=True, text=True,
                         env=env)
    names, vals, mode = [], [], None
    for l in open(raw).read().splitlines():
        if l.startswith("Variables:"):
            mode = "v"
        elif l.startswith("Values:"):
            mode = "x"
        elif mode == "v" and l.startswith("\t"):
            names.append(l.split()[1])
        elif mode == "x":
            vals += [float(t) for t in l.split()]
    if res.returncode != 0 or "v(ehigh)" not in names:
        sys.exit(f"FAIL: ngspice on {cir}: rc {res.returncode}\n{res.stdout[-2000:]}")
    return vals[names.index("v(ehigh)") + 1] / current


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test")
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    p.add_argument("--ngspice-cache", help="a folder for ngspice's answers, by netlist hash")
    a = p.parse_args()
    global NGSPICE_CACHE
    NGSPICE_CACHE = a.ngspice_cache
    exe = os.path.abspath(a.exe)
    val = os.path.join(os.path.abspath(a.src), "inputs", "validation")
    with tempfile.TemporaryDirectory(prefix=f"ohmdem_val_{a.test}_") as wd:
        if a.test == "chain":
            for model, sizes in (("eq1", (1, 10, 40)), ("holm", (0, 1, 10)), ("eq1+holm", (1, 10))):
                for n in sizes:
                    out = os.path.join(wd, f"chain{n}_{model}")
                    log = run(exe, os.path.join(val, "in.chain"), out, N=n, emodel=model)
                    R = read_R(log, "CHAIN_R")
                    areas = []
                    ref = chain_reference(os.path.join(out, "atoms.dump"), 5.88e7, model=model,
                                          areas_out=areas)
                    what = "a single contact" if n == 0 else f"chain of {n}"
                    check(abs(R / ref - 1) < 1e-10,
                          f"{model}, {what}: R = {R:.12g} ohm, closed form {ref:.12g} "
                          f"(rel. diff {R / ref - 1:+.1e})")
            # compute contact/area: one row per contact, S = pi*R*delta (Hertz)
            loc = read_local(os.path.join(wd, "chain10_eq1", "contacts.local"))
            loc = loc[np.argsort(loc[:, 0])]
            err = np.max(np.abs(loc[:, 6] / np.array(areas_ref_10(wd)) - 1))
            check(len(loc) == 11 and err < 1e-10,
                  f"compute contact/area: {len(loc)} rows, areas match Hertz (max rel. error {err:.1e})")
        elif a.test == "chain_no_path":
            out = os.path.join(wd, "gap")
            log = run(exe, os.path.join(val, "in.chain"), out, N=10, gapat=5)
            check(read_R(log, "CHAIN_R") == math.inf, "an open contact in the chain: R = inf")
            check("no conducting path between the electrodes" in log, "said in the log")
            sig = open(os.path.join(out, "signal.txt")).read()
            check("nan" not in sig.lower(), "no NaN in signal.txt")
        elif a.test in ("packing", "packing_contrast"):
            extra = {"gamma2": 5.88e-5} if a.test == "packing_contrast" else {}
            out = os.path.join(wd, a.test)
            log = run(exe, os.path.join(val, "in.packing"), out, **extra)
            R = read_R(log, "PACKING_R")
            n = int(re.search(r"^PACKING_R \S+ contacts (\S+)", log, re.M).group(1))
            ref = ngspice_R(os.path.join(out, "network.cir"), 0.1)
            what = "conductivities 1e12 apart, " if extra else ""
            check(abs(R / ref - 1) < 1e-9,
                  f"packing ({what}{n} contacts): R = {R:.15g} ohm, ngspice {ref:.15g} "
                  f"(rel. diff {R / ref - 1:+.1e})")
            vtk = open(os.path.join(out, "network.vtk")).read()
            m = re.search(r"^LINES (\d+)", vtk, re.M)
            check(vtk.startswith("# vtk DataFile") and m and int(m.group(1)) > n
                  and "SCALARS current" in vtk and "SCALARS potential" in vtk,
                  f"VTK network written ({m.group(1) if m else 0} line cells)")
        elif a.test == "packing_amg":
            # CG preconditioned by algebraic multigrid (hypre) against ngspice, also with
            # conductivities 1e12 apart, and with 1 and 2 processes.
            for extra in ({}, {"gamma2": 5.88e-5}):
                R = []
                for nprocs in (1, 2):
                    out = os.path.join(wd, f"amg{len(extra)}_np{nprocs}")
                    log = run(exe, os.path.join(val, "in.packing"), out, nprocs=nprocs,
                              solver="amg", **extra)
                    R.append(read_R(log, "PACKING_R"))
                iters = int(float(re.search(r"^PACKING_R \S+ contacts \S+ iterations (\S+)",
                                            log, re.M).group(1)))
                # R[0] against ngspice on the netlist of that same (1-process) run
                ref = ngspice_R(os.path.join(wd, f"amg{len(extra)}_np1", "network.cir"), 0.1)
                what = "conductivities 1e12 apart" if extra else "one conductivity"
                check(abs(R[0] / ref - 1) < 1e-9 and iters > 0,
                      f"packing, solver amg ({what}; last step, warm-started: {iters} iterations): "
                      f"R = {R[0]:.15g} ohm, "
                      f"ngspice {ref:.15g} (rel. diff {R[0] / ref - 1:+.1e})")
                check(abs(R[1] / R[0] - 1) < 1e-12,
                      f"packing, solver amg ({what}): R with 1 and 2 processes "
                      f"{R[0]:.17g} / {R[1]:.17g}")
        elif a.test == "packing_mpi":
            R = []
            for nprocs in (1, 2):
                out = os.path.join(wd, f"np{nprocs}")
                R.append(read_R(run(exe, os.path.join(val, "in.packing"), out, nprocs=nprocs),
                                "PACKING_R"))
            check(abs(R[1] / R[0] - 1) < 1e-12,
                  f"packing: R with 1 and 2 processes {R[0]:.17g} / {R[1]:.17g}")
        elif a.test == "chain_distributed":
            # solver distributed (each process assembles its particles' rows, hypre on all
            # processes) against the closed form, in all three models (their node schemes
            # differ), with 1, 2 and 3 processes; the per-atom potentials (computed only when
            # a dump asks for them) against those of the gathered solve (CG stops on the error
            # of R, ~1e-12: the potentials are good to ~1e-6 of the largest); then a chain cut
            # open: R = inf, no NaN.
            for model in ("eq1", "holm", "eq1+holm"):
                out = os.path.join(wd, f"g_{model}")
                run(exe, os.path.join(val, "in.chain"), out, N=10, emodel=model)
                gathered = last_dump_rows(os.path.join(out, "potentials.dump"))
                for nprocs in (1, 2, 3):
                    out = os.path.join(wd, f"d_{model}_{nprocs}")
                    log = run(exe, os.path.join(val, "in.chain"), out, nprocs=nprocs, N=10,
                              emodel=model, solver="distributed")
                    R = read_R(log, "CHAIN_R")
                    ref = chain_reference(os.path.join(out, "atoms.dump"), 5.88e7, model=model)
                    check(abs(R / ref - 1) < 1e-10,
                          f"distributed, {model}, {nprocs} processes: R = {R:.12g} ohm, closed "
                          f"form {ref:.12g} (rel. diff {R / ref - 1:+.1e})")
                    phi = last_dump_rows(os.path.join(out, "potentials.dump"))
                    scale = max(abs(v) for _, v in gathered)
                    worst = max(abs(a[1] - b[1]) for a, b in zip(phi, gathered)) / scale
                    check(len(phi) == len(gathered) == 12 and scale > 0 and worst < 1e-5 and
                          [a[0] for a in phi] == [b[0] for b in gathered],
                          f"distributed, {model}, {nprocs} processes: per-atom potentials = "
                          f"gathered within {worst:.1e} of the largest")
            out = os.path.join(wd, "d_gap")
            log = run(exe, os.path.join(val, "in.chain"), out, nprocs=2, N=10, gapat=5,
                      solver="distributed")
            check(read_R(log, "CHAIN_R") == math.inf, "distributed, an open contact: R = inf")
            sig = open(os.path.join(out, "signal.txt")).read()
            check("nan" not in sig.lower(), "distributed, open chain: no NaN in signal.txt")
        elif a.test == "packing_distributed":
            # solver distributed with 1, 2 and 3 processes against the gathered solve and
            # against ngspice on the netlist of that same network, with one conductivity and
            # with conductivities 1e12 apart.
            for extra in ({}, {"gamma2": 5.88e-5}):
                what = "conductivities 1e12 apart" if extra else "one conductivity"
                out = os.path.join(wd, f"serial{len(extra)}")
                serial = float(thermo_R(run(exe, os.path.join(val, "in.packing"), out,
                                            **extra))[-1])
                ref = ngspice_R(os.path.join(out, "network.cir"), 0.1)
                for nprocs in (1, 2, 3):
                    out = os.path.join(wd, f"dist{len(extra)}_np{nprocs}")
                    R = float(thermo_R(run(exe, os.path.join(val, "in.packing"), out,
                                           nprocs=nprocs, solver="distributed", export="no",
                                           **extra))[-1])
                    check(abs(R / serial - 1) < 1e-10 and abs(R / ref - 1) < 1e-9,
                          f"packing, distributed, {nprocs} processes ({what}): R = {R:.15g} ohm, "
                          f"gathered {serial:.15g} ({R / serial - 1:+.1e}), ngspice {ref:.15g} "
                          f"({R / ref - 1:+.1e})")
            # A packing squeezed over 4 steps (the multigrid setup kept or renewed): the same
            # bits twice with 2 processes, and the gathered solve's R (2 processes too) at
            # every step.
            moving = {"steps": 4, "squeeze": 4e-6, "export": "no"}
            runs = [thermo_R(run(exe, os.path.join(val, "in.packing"), os.path.join(wd, f"m{k}"),
                                 nprocs=2, solver="distributed", **moving)) for k in (0, 1)]
            check(runs[0] == runs[1] and len(runs[0]) == 5,
                  f"packing squeezed, distributed, 2 processes: the same {len(runs[0])} R "
                  f"bit for bit in two runs")
            serial = thermo_R(run(exe, os.path.join(val, "in.packing"), os.path.join(wd, "ms"),
                                  nprocs=2, **moving))
            worst = max(abs(float(a) / float(b) - 1) for a, b in zip(runs[0], serial))
            check(worst < 1e-10 and len(set(serial)) == 5,
                  f"packing squeezed: R changes every step, distributed = gathered within "
                  f"{worst:.1e}")
        else:
            sys.exit(f"unknown test {a.test}")
    finish()


if __name__ == "__main__":
    main()

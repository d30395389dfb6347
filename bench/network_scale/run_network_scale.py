#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Scaling of compute network/resistance on packings (inputs/validation/in.packing).

For each packing size (-var cells N: 4 N^3 spheres) and each process count, runs the deck
squeezed over K steps (R evaluated at the setup and at every step, so that the multigrid
setup can be kept) and reports the wall time per R evaluation in the run loop ("Other" time
of LIGGGHTS' breakdown / K: the evaluations, fix print and the prescribed motion; the pair
style is timed apart), the busiest rank's CPU time per evaluation (CPU of the run minus CPU of
the same run without the compute, over the K + 1 evaluations: on a machine shared with other
jobs wall times stretch, CPU times do not), each rank's peak resident memory, and that of the
same run without the compute (the engine's own memory). Usage:

  bench/network_scale/run_network_scale.py [--exe build/ohmdem] [--cells 14 24 32] [--steps 3]
      [--gathered-max 24] [--today]

--gathered-max: the largest size also run with the gathered solve (every rank holds the
whole network; `gathered` is solver auto on 1 process, `gath.amg` solver amg on 1 and 2).
--today: also the deck as it was before (netlist and VTK exports on, which force the gathered
solve) at the first size >= 24.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "studies"))
from common import INPUTS, MPI_ENV, OHMDEM  # noqa: E402  (studies/common.py)

DECK = os.path.join(INPUTS, "validation", "in.packing")


def run(exe, nprocs, wd, **var):
    # Each rank's peak memory and CPU time from /usr/bin/time, written to a file per rank:
    # Open MPI does not always forward a rank's last stderr lines before mpirun exits.
    os.makedirs(wd, exist_ok=True)
    stamp = os.path.join(wd, "time")
    wrap = ['sh', '-c', 'exec /usr/bin/time -o "$0.${OMPI_COMM_WORLD_RANK:-0}" '
            '-f "RANK_MAXRSS_KB %M CPU_S %U %S" "$@"', stamp]
    cmd = wrap + [exe, "-in", DECK, "-var", "out", wd]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
    env = dict(os.environ, **MPI_ENV)
    res = subprocess.run(cmd, capture_output=True, text=True, env=env)
    out = res.stdout + res.stderr
    if res.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)}\n{out[-3000:]}")
    stamps = "".join(open(f"{stamp}.{r}").read() for r in range(nprocs))
    ranks = re.findall(r"RANK_MAXRSS_KB (\d+) CPU_S (\S+) (\S+)", stamps)
    if len(ranks) != nprocs:
        sys.exit(f"FAIL: {nprocs} ranks, {len(ranks)} time stamps in {stamp}.*")
    other = re.search(r"^Other time \(%\) = (\S+)", out, re.M)
    return {"rss": max(int(m) / 1024.0 for m, _, _ in ranks),
            "cpu": max(float(u) + float(s) for _, u, s in ranks),
            "other": float(other.group(1)) if other else 0.0}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", default=OHMDEM, help="ohmdem [the build's or the install's]")
    p.add_argument("--cells", type=int, nargs="+", default=[14, 24, 32])
    p.add_argument("--steps", type=int, default=3)
    p.add_argument("--gathered-max", type=int, default=24)
    p.add_argument("--today", action="store_true")
    a = p.parse_args()
    exe = os.path.abspath(a.exe)
    rows = []
    print(f"{'spheres':>9} {'solve':>11} {'np':>3} {'s/eval':>8} {'cpu/eval':>8} {'rank MB':>8} "
          f"{'engine MB':>9} {'compute MB':>10} {'compute KB/sphere':>17}")
    with tempfile.TemporaryDirectory(prefix="ohmdem_scale_") as wd:
        for cells in a.cells:
            n = 4 * cells ** 3
            common = {"cells": cells, "steps": a.steps, "squeeze": 1e-5}
            engine = {np_: run(exe, np_, os.path.join(wd, f"e{cells}_{np_}"), network="no",
                               **common) for np_ in (1, 2)}
            # gathered: auto (1 process only: with more, auto goes distributed from 20000
            # spheres) and amg (the gathered multigrid, the distributed solve's counterpart).
            modes = [("distributed", (1, 2), {"solver": "distributed", "export": "no"})]
            if cells <= a.gathered_max:
                modes[:0] = [("gathered", (1,), {"solver": "auto", "export": "no"}),
                             ("gath.amg", (1, 2), {"solver": "amg", "export": "no"})]
            if a.today and cells >= 24 and not any(r[1] == "today" for r in rows):
                modes.insert(0, ("today", (1, 2), {"solver": "auto", "export": "both"}))
            for name, nps, var in modes:
                for np_ in nps:
                    r = run(exe, np_, os.path.join(wd, f"{name}{cells}_{np_}"), **common, **var)
                    t = r["other"] / a.steps
                    # CPU of the busiest rank spent on R: the run's minus the engine-only
                    # run's, over the K + 1 evaluations (a machine shared with other jobs
                    # stretches wall times, not CPU times).
                    cpu = (r["cpu"] - engine[np_]["cpu"]) / (a.steps + 1)
                    comp = r["rss"] - engine[np_]["rss"]
                    rows.append((n, name, np_, t, r["rss"], engine[np_]["rss"], comp, cpu))
                    print(f"{n:>9} {name:>11} {np_:>3} {t:>8.3f} {cpu:>8.3f} {r['rss']:>8.0f} "
                          f"{engine[np_]['rss']:>9.0f} {comp:>10.0f} {comp * 1024 / n:>17.2f}",
                          flush=True)
    print("\nratios (2 processes / 1 process):")
    for n in sorted({r[0] for r in rows}):
        by = {(r[1], r[2]): r for r in rows if r[0] == n}
        one = [by[k] for k in by if k[1] == 1]
        best1 = min(one, key=lambda r: r[3])
        for name in ("today", "gath.amg", "distributed"):
            if (name, 2) in by:
                r2 = by[(name, 2)]
                print(f"  {n:>9} spheres, {name:>11}: wall {r2[3] / best1[3]:.2f}x, busiest "
                      f"rank's CPU {r2[7] / best1[7]:.2f}x of the best 1-process evaluation "
                      f"({best1[1]}); largest rank's memory {r2[4] / best1[4]:.2f}x, compute "
                      f"memory {r2[6] / best1[6]:.2f}x")


if __name__ == "__main__":
    main()

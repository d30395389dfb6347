#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The 3D bearing's step against the planar one and against stock LIGGGHTS, in one run.

    bench/bearing3d/run_bearing3d_bench.py [--steps N] [--repeat K] [--stock-steps M]
                                           [--mesh-error E] [-o OUTDIR]

Scenes (the deck's bearing, machado2014: 13 balls of 12.6 mm, 500 rad/s, dt = 1e-6 s):
  2d        the paper's scene (load force, F = 320 N)
  3d        model 3d under Fr = 320 N and Fa = 160 N (every ball at a contact angle)
each with the mechanics alone (one output at the end) and with R every step (-var Revery 1);
the fastest of K runs of N steps each ("Loop time" of the log). And stock LIGGGHTS' 3D scene of
the same balls: torus-groove STL meshes at alpha0 = 15 deg (make_groove_stl.py, within E of the
torus), one run of M steps (in.stock_groove). Prints the wall time per step, the ratios 3d/2d,
stock/3d, and each scene's wall time per simulated time (1 = real time). Executables:
$OHMDEM (else the build's, studies/common.py), $LIGGGHTS (default liggghts).
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "studies"))
import common  # noqa: E402

DT = 1e-6
SCENES = {
    "2d": {},
    "3d": {"model": "3d", "Fr": "320", "Fa": "160"},
}


def loop_time(log):
    m = re.findall(r"^Loop time of (\S+) on \d+ procs for (\d+) steps", log, re.M)
    return sum(float(t) for t, _ in m) / sum(int(n) for _, n in m)


def run_ohmdem(out, steps, **var):
    os.makedirs(out, exist_ok=True)
    cmd = [common.OHMDEM, "-in", common.BEARING_DECK, "-log", os.path.join(out, "log.txt"),
           "-screen", "none", "-var", "out", out, "-var", "tend", repr(steps * DT),
           "-var", "dt", repr(DT), "-var", "nout", str(steps), "-var", "nthermo", str(steps)]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    subprocess.run(cmd, cwd=out, check=True, capture_output=True)
    return loop_time(open(os.path.join(out, "log.txt")).read())


def stock_groove(out, steps, mesh_error):
    """Stock liggghts on torus-groove meshes; (s/step, triangles) or (None, why)."""
    liggghts = os.environ.get("LIGGGHTS", "liggghts")
    if shutil.which(liggghts) is None:
        return None, f"no '{liggghts}' on PATH"
    meshes = os.path.join(out, "meshes")
    os.makedirs(meshes, exist_ok=True)
    rb, rci, rco, rin, rout = 6.3e-3, 6.55e-3, 6.65e-3, 24e-3, 36.6e-3
    a0, delta = math.radians(15.0), 2e-6
    tri = 0
    for side, rc, R, s in (("inner", rci, rin, 1), ("outer", rco, rout, -1)):
        # race_grooves.h's alpha0 construction; the tube smaller by delta loads the balls.
        rho_c = R + s * (rb + (rc - rb) * math.cos(a0))
        z_c = s * (rc - rb) * math.sin(a0)
        res = subprocess.run([sys.executable, os.path.join(HERE, "make_groove_stl.py"),
                              "--side", side, "--centre-radius", repr(rho_c),
                              f"--centre-z={z_c!r}", "--groove", repr(rc - delta), "--angle", "15",
                              "--half-width", "25", "--max-error", repr(mesh_error),
                              "-o", os.path.join(meshes, side + ".stl")],
                             check=True, capture_output=True, text=True)
        tri += int(re.search(r"(\d+) triangles", res.stdout).group(1))
    run = os.path.join(out, "stock_groove")
    os.makedirs(run, exist_ok=True)
    res = subprocess.run([liggghts, "-in", os.path.join(HERE, "in.stock_groove"), "-var", "steps",
                          str(steps), "-var", "out", run, "-var", "meshdir", meshes,
                          "-log", os.path.join(run, "log.txt")],  # not -screen none: the
                         # mesh reader of LIGGGHTS 3.8 writes to the screen and crashes without one
                         cwd=run, capture_output=True, text=True)
    if res.returncode != 0:
        return None, f"liggghts exited {res.returncode}"
    return loop_time(open(os.path.join(run, "log.txt")).read()), tri


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--steps", type=int, default=20000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--stock-steps", type=int, default=200)
    ap.add_argument("--mesh-error", type=float, default=5e-7)
    ap.add_argument("-o", default="bench_bearing3d_out")
    a = ap.parse_args()
    if a.steps < 1 or a.repeat < 1 or a.stock_steps < 1 or not a.mesh_error > 0:
        sys.exit("ERROR: --steps, --repeat and --stock-steps expect whole numbers >= 1, "
                 "--mesh-error a length > 0 (m)")
    out = os.path.abspath(a.o)
    t = {}
    for name, var in SCENES.items():
        for label, extra in (("mechanics", {}), ("R every step", {"Revery": 1})):
            best = min(run_ohmdem(os.path.join(out, f"{name}_{k}"), a.steps, **var, **extra)
                       for k in range(a.repeat))
            t[name, label] = best
    stock, info = stock_groove(out, a.stock_steps, a.mesh_error)
    print(f"machado2014, 13 balls, 500 rad/s, dt = {DT:g} s; {a.steps} steps, fastest of "
          f"{a.repeat} runs")
    print(f"{'scene':<34} {'wall s/step':>12} {'x 2d':>7} {'wall/simulated':>15}")
    for label in ("mechanics", "R every step"):
        for name in SCENES:
            s = t[name, label]
            print(f"{name + ', ' + label:<34} {s:12.3e} {s / t['2d', label]:7.2f} {s / DT:15.2f}")
    if stock is None:
        print(f"stock LIGGGHTS groove meshes: not run ({info})")
    else:
        x2d = stock / t['2d', 'mechanics']
        print(f"{'stock LIGGGHTS groove meshes':<34} {stock:12.3e} {x2d:7.1f}"
              f" {stock / DT:15.2f}   ({info} triangles within {a.mesh_error:g} m, "
              f"{a.stock_steps} steps; x 3d mechanics {stock / t['3d', 'mechanics']:.0f})")


if __name__ == "__main__":
    main()

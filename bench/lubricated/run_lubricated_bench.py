#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Cost of the lubricated impedance on the SKF 6208 scene (bench/README.md), in one run:
the mechanics alone, the dry R evaluated at every step (-var Revery 1), and the lubricated
bearing's impedance evaluated at every step (-var Revery 1 -var lubricant VG68; the compute
then gives R and Z at each evaluation), with ratios and what each mode gives for the quantity
an instrument measures across the bearing (|Z| and its phase at fexc), and the lubricated mode
with the plain kernel (-var kernel plain) against the default lanes kernel.

Two measures, as bench/resistance: wall time (the fastest of ROUNDS interleaved runs per mode:
a shared machine only ever slows a run down) and, if valgrind is installed, instructions in
the time loop (callgrind, noise-free): over the first 2000 steps (the run-up: the balls still
slide) and per step in steady rolling (runs to 15 and 17 ms, their difference over 2000 steps).
Wall time too in both phases: over the first STEPS steps (the deck's 20 ms, three quarters of
it run-up: the film still thin, its metallic fraction computed) and per step in steady rolling
(in each round, runs of STEPS and STEPS + STEADY steps, their difference over STEADY steps).
The ratios to the dry mode are the medians of each round's (the rounds interleave the modes, so
a drift in the machine's speed cancels), the table's times the fastest.
Usage:

  bench/lubricated/run_lubricated_bench.py [--steps 20000] [--steady 40000] [--rounds 5]
                                           [--no-callgrind] [--reference EXE]

--reference EXE also runs the lubricated mode with another build (e.g. one before a speed
change) and prints the largest relative difference of each lubricated column over the run: the
error a faster path makes against the slower one.
"""
import argparse
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "studies"))
from common import BEARING_DECK, OHMDEM, read_signal  # noqa: E402  (studies/common.py)

MODES = {
    "mechanics": ["-var", "Revery", "0"],
    "dry": ["-var", "Revery", "1"],
    "lubricated": ["-var", "Revery", "1", "-var", "lubricant", "VG68"],
    # the same with the plain kernel (one contact at a time: the reference the lanes match)
    "lub_plain": ["-var", "Revery", "1", "-var", "lubricant", "VG68", "-var", "kernel", "plain"],
}


def run(wd, mode, tend, prefix=(), exe=OHMDEM, name=None):
    out = os.path.join(wd, name or mode)
    log = out + ".log"
    cmd = [*prefix, exe, "-in", BEARING_DECK, "-var", "out", out, "-var", "tend", str(tend),
           "-var", "nout", "1000", "-log", log, "-screen", "none", *MODES[mode]]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return out, log


def loop_time(log):
    m = re.search(r"^Loop time of (\S+)", open(log).read(), re.M)
    return float(m.group(1))


def instructions(wd, mode, tend=0.002):
    """Instructions in the time loop of a run to tend (s)."""
    cg = os.path.join(wd, f"cg.{mode}.{tend:g}")
    run(wd, mode, tend, ["valgrind", "--tool=callgrind", f"--callgrind-out-file={cg}",
                         "--toggle-collect=LAMMPS_NS::Verlet::run(int)"],
        name=f"cg_{mode}_{tend:g}")
    for line in open(cg):
        if line.startswith(("summary:", "totals:")):
            return float(line.split()[1])
    return None


def steady_instructions(wd, mode):
    """Per step in steady rolling: the difference of runs to 15 and 17 ms (the first 15 ms hold
    the run-up: the balls still slide, the film's erfc path is taken)."""
    return (instructions(wd, mode, 0.017) - instructions(wd, mode, 0.015)) / 2000


def kernel_set():
    """The form of the batched contact kernel this CPU runs (race_admittance_batch.cpp takes
    the best of AVX-512 F+DQ, AVX2, SSE2); valgrind reports no AVX-512, so callgrind's
    instructions are always the AVX2 form's where the CPU has AVX2."""
    try:
        flags = next((ln.split(":", 1)[1].split() for ln in open("/proc/cpuinfo")
                      if ln.startswith("flags")), [])
    except OSError:
        flags = []
    if "avx2" in flags and "avx512f" in flags and "avx512dq" in flags:
        return "AVX-512 (eight lanes)"
    return "AVX2 (four lanes)" if "avx2" in flags else "SSE2 (four lanes)"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--steps", type=int, default=20000)
    p.add_argument("--steady", type=int, default=40000,
                   help="steps beyond --steps for the steady rolling wall time (0: none)")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--no-callgrind", action="store_true")
    p.add_argument("--reference", metavar="EXE", help="another ohmdem build to compare with")
    a = p.parse_args()
    tend = a.steps * 1e-6
    with tempfile.TemporaryDirectory(prefix="bench_lub_") as wd:
        rounds = []  # per round and mode: s/step over the first steps, and in steady rolling
        for _ in range(a.rounds):
            r = {}
            for m in MODES:
                short = loop_time(run(wd, m, tend)[1])
                steady_step = math.nan
                if a.steady > 0:
                    long = loop_time(run(wd, m, tend + a.steady * 1e-6, name=m + "_long")[1])
                    steady_step = (long - short) / a.steady
                r[m] = (short / a.steps, steady_step)
            rounds.append(r)
        t = {m: min(r[m][0] for r in rounds) for m in MODES}
        wall_steady = ({m: min(r[m][1] for r in rounds) for m in MODES} if a.steady > 0 else {})

        def paired(m, phase):  # the median over the rounds of m's time over the dry mode's
            return statistics.median(r[m][phase] / r["dry"][phase] for r in rounds)
        steady = {m: read_signal(os.path.join(wd, m, "signal.txt"), t0=0.015) for m in MODES}
        errors = {}
        if a.reference:
            run(wd, "lubricated", tend, exe=a.reference, name="reference")
            ours = read_signal(os.path.join(wd, "lubricated", "signal.txt"))
            ref = read_signal(os.path.join(wd, "reference", "signal.txt"))
            for c in ("Zabs", "Zphase", "Cb", "Rb", "hmin_inner", "hmin_outer", "lambda_min", "R"):
                if c in ref and c in ours:
                    d = abs(ours[c] / ref[c] - 1)
                    errors[c] = float(d[ref[c] != 0].max())
        ir, ir_steady = {}, {}
        if not a.no_callgrind and shutil.which("valgrind"):
            ir = {m: instructions(wd, m) / 2000 for m in MODES}
            ir_steady = {m: steady_instructions(wd, m) for m in MODES}

    def mean(m, c):
        return float(steady[m][c].mean())

    phases = (f"the first {a.steps} steps" + (f" and steady rolling (the {a.steady} after them)"
                                              if wall_steady else ""))
    print(f"SKF 6208, F = 320 N, 500 rad/s, {a.steps} steps, one core; wall: {a.rounds} "
          f"interleaved rounds (the fastest; x dry: the median of the rounds' ratios), {phases}; "
          f"instructions: callgrind, the first 2000 steps and steady rolling; batched contact "
          f"kernel: {kernel_set()}")
    print(f"{'mode':<11} {'s/step':>9} {'x mech':>7} {'x dry':>6} {'eval/mech':>10} "
          + (f"{'steady':>9} {'x dry':>6} " if wall_steady else "")
          + f"{'instr/step':>11} {'x dry':>6} {'eval/mech':>10} {'steady':>9} {'x dry':>6}")
    mech, mech_ir = t["mechanics"], ir.get("mechanics")
    for m in MODES:
        ev = "-" if m == "mechanics" else f"{(t[m] - mech) / mech:.1%}"
        row = f"{m:<11} {t[m]:>9.3e} {t[m] / mech:>7.2f} {paired(m, 0):>6.2f} {ev:>10}"
        if wall_steady:
            row += f" {wall_steady[m]:>9.3e} {paired(m, 1):>6.2f}"
        if ir:
            ev = "-" if m == "mechanics" else f"{(ir[m] - mech_ir) / mech_ir:.1%}"
            row += (f" {ir[m]:>11.0f} {ir[m] / ir['dry']:>6.2f} {ev:>10}"
                    f" {ir_steady[m]:>9.0f} {ir_steady[m] / ir_steady['dry']:>6.2f}")
        print(row)
    eval_wall = (t["lubricated"] - mech) / (t["dry"] - mech)
    line = (f"lubricated / dry: step {paired('lubricated', 0):.2f}x (wall, the first "
            f"{a.steps} steps), evaluation alone {eval_wall:.2f}x (wall, the fastest runs)")
    if wall_steady:
        line += f"; step {paired('lubricated', 1):.2f}x (wall, steady rolling)"
    if ir:
        line += (f"; step {ir['lubricated'] / ir['dry']:.2f}x, evaluation alone "
                 f"{(ir['lubricated'] - mech_ir) / (ir['dry'] - mech_ir):.2f}x (instructions, "
                 f"run-up); step {ir_steady['lubricated'] / ir_steady['dry']:.3f}x "
                 f"(instructions, steady rolling 15-17 ms)")
    print(line + "; goal 1.5x")
    line = (f"kernel lanes / plain: evaluation alone "
            f"{(t['lubricated'] - mech) / (t['lub_plain'] - mech):.2f}x (wall)")
    if ir:
        lanes = ir_steady["lubricated"] - ir_steady["mechanics"]
        plain = ir_steady["lub_plain"] - ir_steady["mechanics"]
        line += f", {lanes / plain:.2f}x (instructions, steady rolling)"
    same = all(bool((steady["lubricated"][c] == steady["lub_plain"][c]).all())
               for c in ("Zabs", "Zphase", "Cb", "Rb", "hmin_inner", "hmin_outer", "lambda_min"))
    print(line + f"; the two signals {'identical' if same else 'DIFFER'}")
    # What an instrument across the bearing reads (|Z|, phase at fexc = 10 kHz), per mode.
    z, ph, cb = mean("lubricated", "Zabs"), mean("lubricated", "Zphase"), mean("lubricated", "Cb")
    r = mean("dry", "R")
    print(f"dry:        |Z| = R = {r:.5g} ohm, phase 0: {r / z - 1:+.4%} in |Z| and "
          f"{-ph:+.4f} rad in phase against the lubricated bearing (lambda_min "
          f"{mean('lubricated', 'lambda_min'):.1f}: no metal touches)")
    print(f"lubricated: |Z| = {z:.5g} ohm, phase {ph:.6f} rad, Cb = {cb:.4g} F, "
          f"Rb = {mean('lubricated', 'Rb'):.4g} ohm (R of the same run {mean('lubricated', 'R'):.5g} ohm)")
    print("mechanics:  no electrical output")
    if errors:
        print("lubricated against --reference, largest relative difference over the run: "
              + ", ".join(f"{c} {e:.1e}" for c, e in errors.items()))


if __name__ == "__main__":
    main()

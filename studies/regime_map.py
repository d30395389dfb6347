#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The lubricated regime map: the phase of the 6208's impedance at fexc = 10 kHz
against the inner ring's speed and the oil's temperature, ISO VG 68 under the paper's load
(F = 320 N), from runs of the real deck on a coarse grid (each 30 ms at dt = 1e-5 s, the
values averaged over its last 2 ms). Writes into OUT:
  regime_map.csv     speed, temperature, lambda_min, Zphase, Zabs, Cb, Rb, R per run
  regime_map.png     the phase map with the lambda = 1 and 3 contours and the paper's point
  regime_map.md      the numbers
Usage: studies/regime_map.py [--jobs N] [--quick] OUT
"""
import argparse
import concurrent.futures
import csv
import math
import os
import shutil
import subprocess

import common

SPEEDS = [2, 5, 10, 20, 50, 100, 200, 500, 1000]  # rad/s
TEMPERATURES = [20, 40, 60, 80, 100, 120]           # C
FIELDS = ["omega", "temperature", "lambda_min", "Zphase", "Zabs", "Cb", "Rb", "R"]
TEND, DT, WINDOW = 0.03, 1e-5, 0.002


def one_run(out, omega, temp):
    case = os.path.join(out, "runs", f"w{omega:g}_T{temp:g}")
    args = common.variables({"out": case, "omega": omega, "temperature": temp,
                             "lubricant": "VG68", "tend": TEND, "dt": DT, "nout": 10})
    common.run(common.deck_command(common.BEARING_DECK, args + ["-log", "none", "-screen",
                                                                "none"]), who="regime_map")
    s = common.read_signal(os.path.join(case, "signal.txt"), t0=TEND - WINDOW)
    return {"omega": omega, "temperature": temp,
            **{k: float(s[k].mean()) for k in FIELDS[2:]}}


def plot(out, rows, speeds, temps):
    """The phase map (gnuplot, as the other studies): colour = arg Z in degrees over
    log10(speed) and temperature, lines lambda_min = 1 (dashed) and 3."""
    grid = {(r["omega"], r["temperature"]): r for r in rows}
    data = os.path.join(out, "regime_map.grid")
    with open(data, "w") as f:
        for t in temps:
            for w in speeds:
                r = grid[(w, t)]
                f.write(f"{math.log10(w)} {t} {math.degrees(r['Zphase'])} {r['lambda_min']}\n")
            f.write("\n")
    cont = os.path.join(out, "regime_map.contours")
    png = os.path.join(out, "regime_map.png")
    xtics = ", ".join(f"'{w:g}' {math.log10(w)}" for w in speeds)
    script = (
        f"set table '{cont}'; set contour base; set cntrparam levels discrete 1,3; "
        f"unset surface; splot '{data}' using 1:2:4 with lines; unset table; reset; "
        f"set terminal pngcairo size 820,480; set output '{png}'; set view map; "
        f"set xtics ({xtics}); set xlabel 'inner ring speed (rad/s)'; "
        f"set ylabel 'oil temperature (C)'; set cblabel 'arg Z (degrees)'; set cbrange [-90:0]; "
        f"set palette defined (0 '#2b0f54', 0.5 '#b73779', 1 '#fcfdbf'); "
        f"set xrange [{math.log10(speeds[0])}:{math.log10(speeds[-1])}]; "
        f"set yrange [{temps[0]}:{temps[-1]}]; set key at graph 0.02, graph 0.97 left top box opaque; "
        f"set title 'SKF 6208, ISO VG 68, F = 320 N: phase of Z at 10 kHz (ohmdem runs)'; "
        f"set pm3d map interpolate 8,8; "
        f"splot '{data}' using 1:2:3 with pm3d notitle, "
        f"'{cont}' using 1:2:($3 < 2 ? 0 : 1/0) with lines lw 2 dt 2 lc rgb 'black' "
        f"title 'lambda_{{min}} = 1', "
        f"'{cont}' using 1:2:($3 > 2 ? 0 : 1/0) with lines lw 2 lc rgb '#00c8ff' "
        f"title 'lambda_{{min}} = 3', "
        f"'-' using 1:2:3 with points pt 3 ps 2.5 lc rgb 'red' title \"the paper's point\"\n"
        f"{math.log10(500)} 40 0\ne\n")
    if shutil.which("gnuplot") is None:
        print("regime_map: no gnuplot on PATH, regime_map.png not drawn")
        return
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--quick", action="store_true", help="a 3 x 2 grid (tests)")
    a = p.parse_args()
    speeds = [10, 100, 1000] if a.quick else SPEEDS
    temps = [40, 100] if a.quick else TEMPERATURES
    os.makedirs(a.out, exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as ex:
        rows = list(ex.map(lambda wt: one_run(a.out, *wt), [(w, t) for t in temps for w in speeds]))
    with open(os.path.join(a.out, "regime_map.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, FIELDS)
        w.writeheader()
        w.writerows(rows)
    plot(a.out, rows, speeds, temps)
    lines = ["# Regime map: SKF 6208 (machado2014), ISO VG 68, F = 320 N, fexc = 10 kHz", "",
             f"Regenerated at {common.made_at()} by `studies/regime_map.py OUT`; each cell one run of "
             f"`in.bearing -var lubricant VG68` ({TEND * 1e3:g} ms, dt {DT:g} s, means over the "
             f"last {WINDOW * 1e3:g} ms). Phase of Z in degrees (lambda_min in brackets).", "",
             "![regime map](regime_map.png)", "",
             "| T (C) \\ omega (rad/s) | " + " | ".join(f"{w:g}" for w in speeds) + " |",
             "|---|" + "---|" * len(speeds)]
    grid = {(r["omega"], r["temperature"]): r for r in rows}
    for t in temps:
        lines.append(f"| {t:g} | " + " | ".join(
            f"{math.degrees(grid[(w, t)]['Zphase']):.1f} ({grid[(w, t)]['lambda_min']:.2g})"
            for w in speeds) + " |")
    open(os.path.join(a.out, "regime_map.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()

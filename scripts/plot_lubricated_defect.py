#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The README figure of a lubricated 6208 with a 1 degree inner-race defect: Cb(t) and |Z|(t)
of the VG68 run beside R(t) of the dry run, same deck, same defect (doc/methods/
lubricated_contact.md, "Defects"). Runs the two decks (a few ms after the sliding phase:
several crossings of the pit) into OUT/dry and OUT/vg68 and draws OUT/lubricated_inner_defect.png
headless with gnuplot (pngcairo); the README's copy is doc/img/lubricated_inner_defect.png.
Usage: plot_lubricated_defect.py OHMDEM OUT [--from T0] [--to T1]"""
import argparse
import os
import subprocess

import numpy as np

import deck_run

FIGURE = "lubricated_inner_defect.png"


def run(exe, folder, **var):
    return deck_run.run("plot_lubricated_defect", exe, folder, **var)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("workdir", metavar="OUT", help="output folder: the runs and the figure")
    ap.add_argument("png", nargs="?", help=argparse.SUPPRESS)
    ap.add_argument("--from", dest="t0", type=float, default=0.016)
    ap.add_argument("--to", dest="t1", type=float, default=0.0225)
    a = ap.parse_args()
    if a.png is not None:  # the former third argument, the figure's path
        ap.error(f"the figure is written into the output folder, OUT/{FIGURE}: give OHMDEM OUT "
                 f"(not a PNG path '{a.png}')")
    a.png = os.path.join(a.workdir, FIGURE)
    common = dict(defect="inner", size=1.0, tend=a.t1, dt=1e-5, nout=1)
    dry = run(os.path.abspath(a.exe), os.path.abspath(os.path.join(a.workdir, "dry")), **common)
    lub = run(os.path.abspath(a.exe), os.path.abspath(os.path.join(a.workdir, "vg68")),
              lubricant="VG68", **common)
    s = dry["time"] >= a.t0
    table = os.path.join(a.workdir, "figure.dat")
    np.savetxt(table, np.column_stack([1e3 * dry["time"][s], dry["R"][s], 1e12 * lub["Cb"][s],
                                       1e-3 * lub["Zabs"][s], dry["n_masked"][s]]),
               header="time_ms R_dry_ohm Cb_pF Zabs_kohm n_masked")
    gp = f"""set terminal pngcairo size 900,820 font ",11"
set output "{os.path.abspath(a.png)}"
set multiplot layout 3,1 title "6208, F = 320 N, 500 rad/s, 1° inner-race pit (5 µm): dry against VG68 at 40 °C, 10 kHz"
set grid
set lmargin 12
set xrange [{1e3 * a.t0}:{1e3 * a.t1}]
set format x ""
set ylabel "dry R (Ω)"
plot "{table}" u 1:2 w l lw 1.5 lc rgb "#1f4e9c" notitle
set ylabel "VG68: Cb (pF)"
plot "{table}" u 1:3 w l lw 1.5 lc rgb "#b0306a" notitle
set format x "%g"
set xlabel "time (ms)"
set ylabel "VG68: |Z| (kΩ)"
plot "{table}" u 1:4 w l lw 1.5 lc rgb "#2a7f3f" notitle
unset multiplot
"""
    subprocess.run(["gnuplot"], input=gp, text=True, check=True)
    print(f"wrote {a.png}")


if __name__ == "__main__":
    main()

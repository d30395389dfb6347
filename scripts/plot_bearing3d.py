#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The README figures of the 3D bearing (model 3d, doc/methods/bearing_3d.md), in VG68 at 40 °C:
- OUT/bearing3d_contact_angle.png: the contact angle over time of a deep-groove bearing (the
  CWRU 6205-2RS JEM, 20 µm radial clearance) under an axial load, and of an angular-contact
  bearing (the paper's bearing with its grooves offset for a 25° nominal angle) under an axial
  preload and a radial load, both rolling at 500 rad/s from rest;
- OUT/bearing3d_capacitance.png: the 6205's capacitance Cb against the axial load, with its
  mean contact angle.
Runs the decks into OUT/<case> (about a minute on one core) and draws with gnuplot (pngcairo);
the README's copies are doc/img/bearing3d_*.png.
Usage: plot_bearing3d.py OHMDEM OUT [--tend T]"""
import argparse
import os
import subprocess

import numpy as np

import deck_run

DEEP = dict(model="3d", bearing="6205-2RS_JEM", clearance=20e-6, Fr=0, lubricant="VG68",
            omega=500)
ANGULAR = dict(model="3d", alpha0=25, preload=15e-6, Fr=800, lubricant="VG68", omega=500)
AXIAL_LOADS = (50, 100, 200, 500, 1000, 2000, 5000)  # N


def run(exe, folder, **var):
    return deck_run.run("plot_bearing3d", exe, folder, **var)


def gnuplot(script):
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("workdir", metavar="OUT", help="output folder: the runs and the figures")
    ap.add_argument("--tend", type=float, default=0.03, help="simulated time of each run (s)")
    a = ap.parse_args()
    exe, out = os.path.abspath(a.exe), os.path.abspath(a.workdir)
    nout = 10
    deep = run(exe, os.path.join(out, "deep_groove"), Fa=1000, tend=a.tend, nout=nout, **DEEP)
    angular = run(exe, os.path.join(out, "angular_contact"), tend=a.tend, nout=nout, **ANGULAR)
    t_table = os.path.join(out, "contact_angle.dat")
    n = min(len(deep["time"]), len(angular["time"]))
    np.savetxt(t_table, np.column_stack([1e3 * deep["time"][:n], deep["alpha_outer_mean"][:n],
                                         deep["alpha_inner_mean"][:n],
                                         angular["alpha_outer_mean"][:n],
                                         angular["alpha_outer_max"][:n]]),
               header="time_ms deep_outer deep_inner angular_outer_mean angular_outer_max")

    rows = []
    for fa in AXIAL_LOADS:
        sig = run(exe, os.path.join(out, f"axial_{fa}"), Fa=fa, tend=a.tend, nout=nout, **DEEP)
        late = sig["time"] > 2 * a.tend / 3  # rolling, after the sliding phase
        rows.append((fa, 1e12 * sig["Cb"][late].mean(), sig["alpha_outer_mean"][late].mean(),
                     1e9 * sig["hmin_inner"][late].mean()))
    c_table = os.path.join(out, "capacitance.dat")
    np.savetxt(c_table, np.array(rows), header="Fa_N Cb_pF alpha_outer_deg hmin_inner_nm")
    for fa, cb, alpha, h in rows:
        print(f"6205-2RS JEM, VG68 40 C, 500 rad/s, Fa {fa:5g} N: Cb {cb:7.2f} pF, "
              f"contact angle {alpha:5.2f} deg, inner film {h:6.1f} nm")

    angle_png = os.path.join(out, "bearing3d_contact_angle.png")
    gnuplot(f"""set terminal pngcairo size 900,420 font ",11"
set output "{angle_png}"
set title "Contact angle from rest to rolling at 500 rad/s (model 3d, VG68)"
set grid
set xlabel "time (ms)"
set ylabel "contact angle (deg)"
set key bottom right
plot "{t_table}" u 1:2 w l lw 2 lc rgb "#1f4e9c" t "6205, 20 µm clearance, Fa 1000 N: outer race", \\
     "{t_table}" u 1:3 w l lw 1 dt 2 lc rgb "#1f4e9c" t "  inner race", \\
     "{t_table}" u 1:4 w l lw 2 lc rgb "#b0306a" t "angular contact, α0 25°, preload 15 µm, Fr 800 N: mean", \\
     "{t_table}" u 1:5 w l lw 1 dt 2 lc rgb "#b0306a" t "  largest"
""")
    cap_png = os.path.join(out, "bearing3d_capacitance.png")
    gnuplot(f"""set terminal pngcairo size 900,420 font ",11"
set output "{cap_png}"
set title "6205-2RS JEM under an axial load, VG68 at 40 °C, 500 rad/s (model 3d)"
set grid
set logscale x
set xrange [30:8000]
set xlabel "axial load Fa (N)"
set ylabel "Cb (pF)"
set y2label "contact angle (deg)"
set ytics nomirror
set y2tics
set key top left
plot "{c_table}" u 1:2 w lp lw 2 pt 7 lc rgb "#1f4e9c" t "capacitance Cb", \\
     "{c_table}" u 1:3 axes x1y2 w lp lw 1 pt 6 dt 2 lc rgb "#b0306a" t "outer contact angle"
""")
    print(f"wrote {angle_png}\nwrote {cap_png}")


if __name__ == "__main__":
    main()

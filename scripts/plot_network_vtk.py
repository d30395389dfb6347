#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Top view of one step of a compute network/resistance VTK series, rendered headless with
gnuplot (pngcairo): the bearing rings and cage (the geometry file), the balls (the particles
file) and the current network (the network file, each conductance coloured by its current).
The figure in README.md: doc/img/bearing_network.png, made by
    build/ohmdem -in inputs/bearing_6208/in.bearing -var out out/vtkfig -var load radial \\
        -var tend 0.01 -var dt 1e-5 -var vtk 500
    /usr/bin/python3 scripts/plot_network_vtk.py out/vtkfig/vtk/network.pvd doc/img/bearing_network.png
Usage: plot_network_vtk.py PVD PNG [--time T (default: the last)] [--title TEXT]"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtk_legacy import read_pvd, read_vtk  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pvd")
    ap.add_argument("png")
    ap.add_argument("--time", type=float)
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    series = read_pvd(a.pvd)
    t = a.time if a.time is not None else max(series)
    if t not in series:
        sys.exit(f"ERROR: --time {t}: not in {a.pvd} (times {sorted(series)})")
    files = [os.path.join(os.path.dirname(a.pvd), f) for f in series[t]]
    if len(files) < 3:
        sys.exit(f"ERROR: {a.pvd}: no bearing geometry file at time {t}")
    net_p, net_c, net_d, _ = read_vtk(files[0])
    ball_p, _, ball_d, _ = read_vtk(files[1])
    geo_p, geo_c, geo_d, _ = read_vtk(files[2])

    with tempfile.TemporaryDirectory() as tmp:
        mm = 1e3  # drawn in mm
        # Rings: the radial extent of each body's surface about its own centre.
        body = geo_d[("CELL_DATA", "body")]
        objects = []
        for b, fill in ((1, "#b0b7bf"), (0, "#b0b7bf")):
            idx = sorted({i for c, kb in zip(geo_c["POLYGONS"], body) if kb == b for i in c})
            c = geo_p[idx, :2].mean(axis=0)
            r = np.hypot(*(geo_p[idx, :2] - c).T)
            if b == 1:  # outer race: from its groove bottom outward
                objects.append((c, r.max() * 1.12, fill))
                objects.append((c, r.max(), "white"))
            else:  # inner race: a ring up to its groove bottom, its bore left open
                objects.append((c, r.min(), fill))
                objects.append((c, 0.7 * r.min(), "white"))
        idx = sorted({i for c, kb in zip(geo_c["POLYGONS"], body) if kb == 2 for i in c})
        cage_c = geo_p[idx, :2].mean(axis=0)
        cage_r = np.hypot(*(geo_p[idx, :2] - cage_c).T).mean()
        with open(os.path.join(tmp, "balls.dat"), "w") as f:
            for p, r in zip(ball_p, ball_d[("POINT_DATA", "radius")]):
                f.write(f"{p[0] * mm} {p[1] * mm} {r * mm}\n")
        current = np.abs(net_d[("CELL_DATA", "current")])
        with open(os.path.join(tmp, "edges.dat"), "w") as f:
            for cell, i in zip(net_c.get("LINES", []), current):
                p, q = net_p[cell[0]], net_p[cell[1]]
                f.write(f"{p[0] * mm} {p[1] * mm} {(q[0] - p[0]) * mm} {(q[1] - p[1]) * mm} "
                        f"{i * 1e3}\n")
        with open(os.path.join(tmp, "points.dat"), "w") as f:
            for p in net_p:
                f.write(f"{p[0] * mm} {p[1] * mm}\n")
        lim = max(r for _, r, _ in objects) * mm * 1.05
        gp = [f"set terminal pngcairo size 900,800 font 'DejaVu Sans,12'",
              f"set output '{os.path.abspath(a.png)}'",
              "set size ratio -1", f"set xrange [{-lim}:{lim}]", f"set yrange [{-lim}:{lim}]",
              "set xlabel 'x (mm)'", "set ylabel 'y (mm)'",
              f"set title '{a.title or f'ohmdem: current network at t = {t * 1e3:g} ms'}'",
              "set cblabel 'current through the ball (mA)'",
              "set palette defined (0 '#2c7bb6', 0.5 '#fdae61', 1 '#d7191c')",
              f"set cbrange [0:{max(current.max() * 1e3, 1e-12)}]"]
        for n, (c, r, fill) in enumerate(objects, start=1):
            gp.append(f"set object {n} circle at {c[0] * mm},{c[1] * mm} size {r * mm} "
                      f"fc rgb '{fill}' fs solid 1.0 noborder behind")
        n = len(objects) + 1
        gp.append(f"set object {n} circle at {cage_c[0] * mm},{cage_c[1] * mm} size "
                  f"{cage_r * mm} fs empty border lc rgb '#6a3d9a' dt 2 lw 2 front")
        gp.append(f"set label 1 'cage (pitch circle)' at {cage_c[0] * mm},{-cage_r * mm * 0.93}"
                  " center tc rgb '#6a3d9a' front")
        gp.append("plot '%s' using 1:2:3 with circles fs transparent solid 0.35 lc rgb '#4d4d4d' "
                  "notitle, '%s' using 1:2:3:4:5 with vectors nohead lw 5 lc palette notitle, "
                  "'%s' using 1:2 with points pt 7 ps 0.6 lc rgb 'black' notitle"
                  % (os.path.join(tmp, "balls.dat"), os.path.join(tmp, "edges.dat"),
                     os.path.join(tmp, "points.dat")))
        res = subprocess.run(["gnuplot"], input="\n".join(gp) + "\n", text=True,
                             capture_output=True)
        if res.returncode != 0:
            sys.exit(f"ERROR: gnuplot: {res.stderr}")
    print(f"wrote {a.png} (time {t} s, {len(current)} conductances)")


if __name__ == "__main__":
    main()

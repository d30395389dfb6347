#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The demo's kinematics figure (scripts/plot_kinematics.gp) plots the signal's named columns:
every curve's points, as gnuplot's `set table` writes them, equal the column its title names
(cage: omega_cage, inner race: fn_inner_mean, outer race: fn_outer_mean) of a short run's
signal.txt, to gnuplot's 6 significant digits. The script once plotted the ball-set speed as
the "mean ball load" (an old column layout). The healthy figure's offsets (plot_offset.gp) are
R minus its mean over the window, in micro-ohm.

Usage: demo_plot_tests.py --exe OHMDEM --src SOURCE_DIR
"""
import argparse
import os
import subprocess
import tempfile

from deck_checks import check, finish, read_signal


def curves(path):
    """{title: [(x, y), ...]} of a gnuplot table file."""
    out, title = {}, None
    for line in open(path):
        if line.startswith("# Curve ") and " of " in line:  # a curve (untitled: its number)
            title = line.split(",")[0]
            out[title] = []
        elif line.startswith("# Curve title:"):
            out[line.split(":", 1)[1].strip().strip('"')] = out.pop(title)
            title = line.split(":", 1)[1].strip().strip('"')
        elif line.strip() and not line.startswith("#") and title is not None:
            x, y, kind = line.split()[:3]
            if kind != "u":  # undefined: outside the window
                out[title].append((float(x), float(y)))
    return out


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    a = p.parse_args()
    with tempfile.TemporaryDirectory(prefix="demo_plot_") as work:
        r = subprocess.run([a.exe, "-in", os.path.join(a.src, "inputs", "bearing_6208",
                                                       "in.bearing"),
                            "-var", "out", "run", "-var", "tend", "3e-4", "-screen", "none",
                            "-log", "none"], cwd=work)
        check(r.returncode == 0, f"the run (exit {r.returncode})")
        g = subprocess.run(["gnuplot", "-e", "sig='run/signal.txt'; png='k.png'; "
                            "tablefile='k.txt'", os.path.join(a.src, "scripts",
                                                             "plot_kinematics.gp")], cwd=work)
        check(g.returncode == 0, f"gnuplot (exit {g.returncode})")
        s = read_signal(os.path.join(work, "run", "signal.txt"))
        got = curves(os.path.join(work, "k.txt"))
        for title, column in (("cage (simulated)", "omega_cage"), ("inner race", "fn_inner_mean"),
                              ("outer race", "fn_outer_mean")):
            pts = got.get(title, [])
            ok = len(pts) == len(s["time"]) and all(
                abs(x - t) <= 1e-5 * abs(t) + 1e-12 and abs(y - v) <= 1e-5 * abs(v) + 1e-9
                for (x, y), t, v in zip(pts, s["time"], s[column]))
            check(ok, f"'{title}' plots {column} ({len(pts)} points)")
        # plot_offset.gp: R - R0 in micro-ohm over the window, R0 its mean there
        t0, t1 = 1.0005e-4, 2.9995e-4  # edges between rows: no rounding question
        g = subprocess.run(["gnuplot", "-e", f"sig='run/signal.txt'; png='d.png'; name='t'; "
                            f"t0={t0}; t1={t1}; tablefile='d.txt'",
                            os.path.join(a.src, "scripts", "plot_offset.gp")], cwd=work)
        keep = (s["time"] >= t0) & (s["time"] <= t1)
        want = 1e6 * (s["R"][keep] - s["R"][keep].mean())
        pts = [p for c in curves(os.path.join(work, "d.txt")).values() for p in c]
        ok = g.returncode == 0 and len(pts) == len(want) and all(
            abs(y - w) <= 1e-5 * abs(w) + 1e-6 * abs(want).max() for (_, y), w in zip(pts, want))
        check(ok, f"plot_offset.gp plots 1e6 (R - mean R) over [{t0}, {t1}] ({len(pts)} points)")
    finish()


if __name__ == "__main__":
    main()

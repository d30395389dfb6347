#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The VTK/netlist series of compute network/resistance read back (numpy, no VTK library):
every legacy-VTK file parses (counts consistent, data arrays of the right length, finite),
the .pvd lists exactly the written steps with their times and files, and the bearing's
geometry file draws the deck's Dext, Dinn and pitch diameter Dp = (Dext + Dinn)/2.
Usage: vtk_series_tests.py TEST --exe OHMDEM --src SOURCE_DIR"""
import argparse
import glob
import os
import re
import sys
import tempfile
import numpy as np

from deck_checks import check, finish
from validation_tests import run

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "scripts"))
from vtk_legacy import read_pvd, read_vtk  # noqa: E402  (scripts/: also the figure's reader)


def check_series(folder, pattern_re, expected_steps, dt, what):
    files = glob.glob(os.path.join(folder, "*.vtk"))
    bad = []
    for f in files:
        try:
            read_vtk(f)
        except (ValueError, IndexError) as e:
            bad.append(f"{os.path.basename(f)}: {e}")
    check(files and not bad, f"{what}: {len(files)} VTK files parse" + (f" ({bad[:3]})" if bad else ""))
    written = sorted(int(re.fullmatch(pattern_re, os.path.basename(f)).group(1))
                     for f in files if re.fullmatch(pattern_re, os.path.basename(f)))
    check(written == expected_steps, f"{what}: network files of steps {written}, expected "
          f"{expected_steps}")
    pvd = read_pvd(os.path.join(folder, "network.pvd"))
    times = sorted(pvd)
    check(np.allclose(times, [s * dt for s in expected_steps], rtol=1e-12, atol=0),
          f"{what}: network.pvd lists the times {times} (steps x dt)")
    listed_ok = all(re.fullmatch(pattern_re, pvd[t][0]) and
                    int(re.fullmatch(pattern_re, pvd[t][0]).group(1)) * dt == t and
                    all(os.path.exists(os.path.join(folder, f)) for f in pvd[t]) for t in times)
    check(listed_ok, f"{what}: each time lists its own network file first, every listed file "
          "exists")
    return pvd


def test_bearing(r):
    out = os.path.join(r.wd, "bearing")
    dt = 1e-5
    run(r.exe, os.path.join(r.src, "inputs", "bearing_6208", "in.bearing"), out, tend=0.003,
        dt=dt, vtk=100, here=os.path.join(r.src, "inputs", "bearing_6208"),
        catalog=os.path.join(r.src, "inputs", "bearings"))
    folder = os.path.join(out, "vtk")
    pvd = check_series(folder, r"network\.(\d+)\.vtk", [0, 100, 200, 300], dt, "bearing")
    # The deck's dimensions: the catalog entry it ran (inputs/bearings/machado2014).
    cat = dict(re.findall(r"variable\s+(\w+)\s+index\s+(\S+)",
                          open(os.path.join(r.src, "inputs", "bearings", "machado2014")).read()))
    dext, dinn = float(cat["Dext"]), float(cat["Dinn"])
    dp = 0.5 * (dext + dinn)
    geometry = sorted({files[2] for files in pvd.values() if len(files) > 2})
    check(len(geometry) >= 1, f"bearing: the geometry file(s) {geometry} in every step of the pvd")
    pts, cells, data, field = read_vtk(os.path.join(folder, geometry[0]))
    body = data[("CELL_DATA", "body")]
    quads = cells["POLYGONS"]

    def radii(b):
        idx = sorted({i for c, kb in zip(quads, body) if kb == b for i in c})
        return np.hypot(pts[idx, 0], pts[idx, 1])

    inner, outer, cage = radii(0), radii(1), radii(2)
    # The outer ring is pressed on the balls (radius - interference of a few um): 1e-4.
    check(abs(outer.max() - dext / 2) < 1e-4 * dext and abs(inner.min() - dinn / 2) < 1e-12
          and np.all(np.abs(cage - dp / 2) < 1e-12),
          f"bearing geometry: outer groove bottom {2 * outer.max():.9g} m (Dext {dext}), inner "
          f"{2 * inner.min():.9g} m (Dinn {dinn}), cage {2 * cage.mean():.9g} m (Dp {dp:.9g})")
    check(np.allclose(field["radius"], [dinn / 2, outer.max(), dp / 2], rtol=1e-12),
          f"bearing geometry: field data radius {field['radius']}")
    parts = pvd[max(pvd)]
    _, _, pdata, _ = read_vtk(os.path.join(folder, parts[1]))
    check(len(pdata[("POINT_DATA", "radius")]) == 13, "bearing: 13 balls in the particles file")


def test_packing(r):
    out = os.path.join(r.wd, "packing")
    run(r.exe, os.path.join(r.src, "inputs", "validation", "in.packing"), out,
        netlist=os.path.join(out, "net.*.cir"), vtk=os.path.join(out, "network.*.vtk"),
        cells=3)
    check(sorted(os.path.basename(f) for f in glob.glob(os.path.join(out, "net.*.cir"))) ==
          ["net.0.cir", "net.1.cir"], "packing: netlist series net.0.cir, net.1.cir (run 1)")
    check_series(out, r"network\.(\d+)\.vtk", [0, 1], 1e-7, "packing")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("test", choices=["bearing", "packing"])
    ap.add_argument("--exe", required=True)
    ap.add_argument("--src", required=True)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="vtkseries_") as wd:
        r = argparse.Namespace(exe=os.path.abspath(a.exe), src=os.path.abspath(a.src), wd=wd)
        globals()["test_" + a.test](r)
    finish()


if __name__ == "__main__":
    main()

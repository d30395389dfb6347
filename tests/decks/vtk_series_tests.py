#!/usr/bin/python3
"""The VTK/netlist series of compute network/resistance read back (numpy, no VTK library):
every legacy-VTK file parses (counts consistent, data arrays of the right length, finite),
the .pvd lists exactly the written steps with their times and files, and the bearing's
geometry file draws the deck's Dext, Dinn and pitch diameter Dp = (Dext + Dinn)/2.
Usage: vtk_series_tests.py TEST --exe OHMDEM --src SOURCE_DIR"""
import argparse
import glob
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import numpy as np

from deck_checks import check, finish


def run(exe, deck, out, **var):
    os.makedirs(out, exist_ok=True)
    cmd = [exe, "-in", deck, "-log", os.path.join(out, "log.txt"), "-screen", "none",
           "-var", "out", out]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    res = subprocess.run(cmd, cwd=out, capture_output=True, text=True)
    if res.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)}\n{res.stdout[-2000:]}{res.stderr[-2000:]}")


def read_vtk(path):
    """A legacy ASCII POLYDATA file: points, cells {kind: [index lists]}, data {name: array},
    field data; raises ValueError on any inconsistency."""
    tok = open(path).read().split("\n")
    if not tok[0].startswith("# vtk DataFile") or tok[2].strip() != "ASCII" or \
            tok[3].strip() != "DATASET POLYDATA":
        raise ValueError("not an ASCII legacy POLYDATA file")
    words = " ".join(tok[4:]).split()
    k, pts, cells, data, field, where = 0, None, {}, {}, {}, None
    ncell = npoint = 0
    while k < len(words):
        w = words[k]
        if w == "POINTS":
            n = int(words[k + 1])
            pts = np.array(words[k + 3:k + 3 + 3 * n], dtype=float).reshape(n, 3)
            k += 3 + 3 * n
        elif w in ("VERTICES", "LINES", "POLYGONS"):
            n, size = int(words[k + 1]), int(words[k + 2])
            vals = list(map(int, words[k + 3:k + 3 + size]))
            lists, j = [], 0
            for _ in range(n):
                lists.append(vals[j + 1:j + 1 + vals[j]])
                j += 1 + vals[j]
            if j != size:
                raise ValueError(f"{w}: size {size}, read {j}")
            cells[w] = lists
            k += 3 + size
        elif w in ("CELL_DATA", "POINT_DATA"):
            where = w
            if w == "CELL_DATA":
                ncell = int(words[k + 1])
            else:
                npoint = int(words[k + 1])
            k += 2
        elif w == "SCALARS":
            name = words[k + 1]
            n = ncell if where == "CELL_DATA" else npoint
            k += 3
            if words[k].isdigit():  # the optional number of components
                k += 1
            if words[k] == "LOOKUP_TABLE":
                k += 2
            data[(where, name)] = np.array(words[k:k + n], dtype=float)
            k += n
        elif w == "FIELD":
            arrays = int(words[k + 2])
            k += 3
            for _ in range(arrays):
                name, comp, tup = words[k], int(words[k + 1]), int(words[k + 2])
                field[name] = np.array(words[k + 4:k + 4 + comp * tup], dtype=float)
                k += 4 + comp * tup
        else:
            raise ValueError(f"unexpected '{w}'")
    total = sum(len(c) for c in cells.values())
    if pts is None or not np.all(np.isfinite(pts)):
        raise ValueError("no or non-finite points")
    for lists in cells.values():
        if any(i < 0 or i >= len(pts) for c in lists for i in c):
            raise ValueError("a cell refers to a missing point")
    if ncell and ncell != total:
        raise ValueError(f"CELL_DATA {ncell} for {total} cells")
    if npoint and npoint != len(pts):
        raise ValueError(f"POINT_DATA {npoint} for {len(pts)} points")
    for (where, name), a in data.items():
        if len(a) != (ncell if where == "CELL_DATA" else npoint) or not np.all(np.isfinite(a)):
            raise ValueError(f"{name}: wrong length or not finite")
    return pts, cells, data, field


def read_pvd(path):
    """{time: [files by part]} of a ParaView collection."""
    steps = {}
    for ds in ET.parse(path).getroot().iter("DataSet"):
        steps.setdefault(float(ds.get("timestep")), {})[int(ds.get("part"))] = ds.get("file")
    return {t: [parts[p] for p in sorted(parts)] for t, parts in steps.items()}


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
    # The deck's dimensions: the catalog entry it ran (inputs/bearings/6208).
    cat = dict(re.findall(r"variable\s+catalog_(\w+)\s+index\s+(\S+)",
                          open(os.path.join(out, "bearing.lmp")).read()))
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

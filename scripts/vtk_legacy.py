# SPDX-License-Identifier: GPL-2.0-or-later
"""Reader of the legacy ASCII VTK POLYDATA files and ParaView .pvd collections that compute
network/resistance writes (numpy only: no VTK library needed). Raises ValueError on any
inconsistency, so it doubles as a format check (tests/decks/vtk_series_tests.py)."""
import xml.etree.ElementTree as ET

import numpy as np


def read_vtk(path):
    """(points (n, 3), cells {VERTICES|LINES|POLYGONS: [index lists]},
    data {(CELL_DATA|POINT_DATA, name): array}, field {name: array})."""
    lines = open(path).read().split("\n")
    if not lines[0].startswith("# vtk DataFile") or lines[2].strip() != "ASCII" or \
            lines[3].strip() != "DATASET POLYDATA":
        raise ValueError("not an ASCII legacy POLYDATA file")
    words = " ".join(lines[4:]).split()
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
    """{time: [files by part]} of a ParaView collection (files relative to the .pvd)."""
    steps = {}
    for ds in ET.parse(path).getroot().iter("DataSet"):
        steps.setdefault(float(ds.get("timestep")), {})[int(ds.get("part"))] = ds.get("file")
    return {t: [parts[p] for p in sorted(parts)] for t, parts in steps.items()}

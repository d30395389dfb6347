#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Small NumPy .npy files for the .npy reader tests (tests/post/io/test_read_npy.cpp), written by numpy
itself (numpy.save / numpy.lib.format.write_array), independent of ohmdem's writer.

x(k) = 0.5 sin(2 pi 50 k / 1000) + 0.01 k, k = 0..299, sampled at 1 kHz (t = k / 1000 s).

  table.npy       records: time (<f8), x (<f8), n (<i4, round(1000 x)): a signal table
  table_v2.npy    the same, format version 2.0
  plain.npy       1-D float32 x
  c2d.npy         2-D (300, 3) float64 [t, x, 2x], C order
  f2d.npy         the same, Fortran order
  int16.npy       1-D int16 round(1000 x)
  uncounted.npy   table.npy whose header counts 290 rows (10 written after the last count)
  big.npy         1-D '>f8' (big-endian): refused
  complex.npy     1-D complex128: refused
  cut.npy         c2d.npy without its last 10 bytes: refused (truncated)
  cut_record.npy  table.npy without its last 7 bytes (inside its last counted row): refused
  subarray.npy    records with a (2,)-shaped field: refused
Run: /usr/bin/python3 tests/post/make_npy_fixtures.py
"""
import os

import numpy as np

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "npy")


def main():
    os.makedirs(HERE, exist_ok=True)
    k = np.arange(300)
    t = k / 1000.0
    x = 0.5 * np.sin(2 * np.pi * 50 * t) + 0.01 * k
    table = np.zeros(300, dtype=[("time", "<f8"), ("x", "<f8"), ("n", "<i4")])
    table["time"], table["x"], table["n"] = t, x, np.round(1000 * x)
    np.save(os.path.join(HERE, "table.npy"), table)
    with open(os.path.join(HERE, "table_v2.npy"), "wb") as f:
        np.lib.format.write_array(f, table, version=(2, 0))
    np.save(os.path.join(HERE, "plain.npy"), x.astype(np.float32))
    c2d = np.column_stack([t, x, 2 * x])
    np.save(os.path.join(HERE, "c2d.npy"), c2d)
    np.save(os.path.join(HERE, "f2d.npy"), np.asfortranarray(c2d))
    np.save(os.path.join(HERE, "int16.npy"), np.round(1000 * x).astype(np.int16))
    raw = open(os.path.join(HERE, "table.npy"), "rb").read()
    assert raw.count(b"(300,)") == 1
    open(os.path.join(HERE, "uncounted.npy"), "wb").write(raw.replace(b"(300,)", b"(290,)"))
    np.save(os.path.join(HERE, "big.npy"), x.astype(">f8"))
    np.save(os.path.join(HERE, "complex.npy"), x.astype(np.complex128))
    raw = open(os.path.join(HERE, "c2d.npy"), "rb").read()
    open(os.path.join(HERE, "cut.npy"), "wb").write(raw[:-10])
    raw = open(os.path.join(HERE, "table.npy"), "rb").read()
    open(os.path.join(HERE, "cut_record.npy"), "wb").write(raw[:-7])
    np.save(os.path.join(HERE, "subarray.npy"), np.zeros(4, dtype=[("v", "<f8", (2,))]))


if __name__ == "__main__":
    main()

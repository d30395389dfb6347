#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Small MATLAB files for the .mat reader tests (tests/post/io/test_read_mat.cpp), written with
scipy.io.savemat (MAT v5, uncompressed unless named _z; one v4 file).

  good.mat     x (1x300 double: 0.5 sin(2 pi 50 t) + 0.01 k at 1 kHz), y (300x1 single, 2 x),
               n16 (300x1 int16, round(1000 x)), fs (1x1 double 1000), RPM (1x1 uint16 1797)
  good_z.mat   the same, compressed (savemat do_compression=True)
  good_v4.mat  x and fs as MAT v4
  bad.mat      c (complex vector), m (3x4 double matrix), s (struct), cell (cell array),
               name (char), e (empty 0x0 double), nan (vector with a NaN), only vector v
  not_mat.mat  a text file with the .mat extension
  zero_rpm.mat x (1x300 double) and RPM (1x1 double 0): a recorded speed that is no speed
Run: /usr/bin/python3 tests/post/make_mat_fixtures.py
"""
import os

import numpy as np
import scipy.io

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "mat")


def main():
    os.makedirs(HERE, exist_ok=True)
    k = np.arange(300)
    x = 0.5 * np.sin(2 * np.pi * 50 * k / 1000.0) + 0.01 * k
    good = {"x": x.reshape(1, -1), "y": (2 * x).astype(np.float32).reshape(-1, 1),
            "n16": np.round(1000 * x).astype(np.int16).reshape(-1, 1),
            "fs": np.array([[1000.0]]), "RPM": np.array([[1797]], dtype=np.uint16)}
    scipy.io.savemat(os.path.join(HERE, "good.mat"), good)
    scipy.io.savemat(os.path.join(HERE, "good_z.mat"), good, do_compression=True)
    scipy.io.savemat(os.path.join(HERE, "good_v4.mat"), {"x": x.reshape(-1, 1),
                                                          "fs": np.array([[1000.0]])}, format="4")
    v = np.arange(10.0)
    nan = v.copy()
    nan[4] = np.nan
    bad = {"c": (v + 1j * v).reshape(-1, 1), "m": np.arange(12.0).reshape(3, 4),
           "s": {"a": 1.0, "b": v}, "cell": np.array([[v, "txt"]], dtype=object),
           "name": "DE_time", "e": np.zeros((0, 0)), "nan": nan.reshape(-1, 1),
           "v": v.reshape(-1, 1)}
    scipy.io.savemat(os.path.join(HERE, "bad.mat"), bad)
    scipy.io.savemat(os.path.join(HERE, "zero_rpm.mat"),
                     {"x": x.reshape(1, -1), "RPM": np.array([[0.0]])})
    with open(os.path.join(HERE, "not_mat.mat"), "w") as f:
        f.write("1\n2\n3\n")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Damaged MAT files are refused by `ohmdem-post` as scipy.io.loadmat refuses them: copies of the
fixtures of tests/post/data/mat cut in half (uncompressed, compressed, v4) or with 40 bytes of a
compressed variable inverted. For each, scipy (the reference) raises, and `ohmdem-post stats`
and `diagnose` exit 1 with one "ERROR: FILE: damaged MAT file: ..." line; the untouched
fixtures are read by both.

usage: damaged_mat.py --post OHMDEM_POST --data tests/post/data/mat
"""
import argparse
import os
import subprocess
import sys
import tempfile

import scipy.io


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    return not ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--post", required=True)
    ap.add_argument("--data", required=True)
    a = ap.parse_args()
    failed = False
    with tempfile.TemporaryDirectory(prefix="damaged_mat_") as work:
        def copy(name, as_name, keep=None, flip=None):
            b = bytearray(open(os.path.join(a.data, name), "rb").read())
            if flip:
                for k in range(flip[0], flip[0] + flip[1]):
                    b[k] ^= 0xFF
            path = os.path.join(work, as_name)
            open(path, "wb").write(bytes(b[:keep] if keep is not None else b))
            return path, len(b)

        cases = []
        for name in ("good.mat", "good_z.mat", "good_v4.mat"):
            size = os.path.getsize(os.path.join(a.data, name))
            cases.append(copy(name, "cut_" + name, keep=size // 2)[0])
        cases.append(copy("good_z.mat", "flipped_z.mat", flip=(300, 40))[0])
        for path in cases:
            name = os.path.basename(path)
            try:
                scipy.io.loadmat(path)
                refused = "read it"
            except Exception as e:  # the reference refuses: ValueError, OSError, zlib.error
                refused = f"{type(e).__name__}: {e}"
            failed |= check(refused != "read it", f"{name}: scipy refuses it ({refused[:70]})")
            for cmd in (["stats", path, "--variable", "x", "--rate", "1000"],
                        ["diagnose", path, "--variable", "x", "--rate", "1000",
                         "--bearing", "6205-2RS_JEM", "--rpm", "1797"]):
                r = subprocess.run([a.post] + cmd, capture_output=True, text=True)
                lines = r.stderr.strip().splitlines()
                failed |= check(r.returncode == 1 and len(lines) == 1
                                and lines[0].startswith(f"ERROR: {path}: damaged MAT file: "),
                                f"{name}: {cmd[0]} refuses it: {r.stderr.strip()}")
        for name in ("good.mat", "good_z.mat", "good_v4.mat"):
            path = os.path.join(a.data, name)
            scipy.io.loadmat(path)
            r = subprocess.run([a.post, "stats", path, "--variable", "x", "--rate", "1000"],
                               capture_output=True, text=True)
            failed |= check(r.returncode == 0, f"{name} (whole): read ({r.stderr.strip()})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

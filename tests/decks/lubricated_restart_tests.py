#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Restart of the lubricated 6208 (project standard: a run split by write_restart /
read_restart gives the same result as one run). One run of the deck with a lubricant, the
signal written every step, against the same run split in two the deck's way (in.restart_first
writes half.restart, the second half starts with -var start restart, as deck_restart does for
the dry bearing). Every column of the second half, the lubricated ones and R among them, must
be the single run's to the last bit: fix signal/table writes the shortest text that reads back
to the same double (std::to_chars), so equal text is equal bits.
Usage: lubricated_restart_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import os

from bearing_tests import run_named_test
from deck_checks import check

LUB_COLUMNS = ["Zabs", "Zphase", "Cb", "Rb", "hmin_inner", "hmin_outer", "lambda_min"]
# 3000 steps of 1e-5 s, split at 15 ms: the halves straddle the end of the sliding phase (11.4
# ms), so the second half starts with balls still settling into rolling.
DT, TEND, THALF = 1e-5, 0.03, 0.015
# Not the deck's defaults (doc/methods/lubricated_contact.md), so that each keyword's value must come
# back from the deck with the restart: a warmer VG68, rougher surfaces, another frequency and
# wetted radius.
LUBRICANT = dict(lubricant="VG68", temperature=60.0, roughness=1.5e-7, fexc=20000.0,
                 wetted=0.0015)


def read_rows(folder):
    """signal.txt's column names and its rows as lists of number texts."""
    lines = open(os.path.join(folder, "signal.txt")).read().splitlines()
    return lines[0].lstrip("#").split(), [l.split() for l in lines[1:]]


def split_against_single(r, label, **var):
    deck_vars = dict(LUBRICANT, dt=DT, nout=1, **var)
    full, _ = r.run(f"{label}_full", tend=TEND, **deck_vars)
    first, _ = r.run(f"{label}_first", deck=os.path.join(os.path.dirname(__file__),
                                                         "in.restart_first"),
                     bearing_deck=r.deck, tend=THALF, **deck_vars)
    second, _ = r.run(f"{label}_second", tend=TEND, start="restart",
                      restart_file=os.path.join(first, "half.restart"), **deck_vars)
    names, a = read_rows(full)
    names_b, b = read_rows(second)
    check(names == names_b and all(c in names for c in LUB_COLUMNS + ["R"]),
          f"{label}: both runs write the lubricated columns and R")
    # A row per step after the start (none at t = 0); the second run, in its own folder, has the
    # rows of the second half.
    n = round((TEND - THALF) / DT)
    check(len(a) == round(TEND / DT) and len(b) == n,
          f"{label}: {len(a)} rows in the single run, {len(b)} in the continued one")
    tail_a, tail_b = a[-n:], b[-n:]
    for j, name in enumerate(names):
        bad = [k for k in range(n) if tail_a[k][j] != tail_b[k][j]]
        if name in LUB_COLUMNS + ["R"] or bad:
            where = f", first at t = {tail_a[bad[0]][0]}" if bad else ""
            check(not bad, f"{label}: {name} of the second half ({n} steps) bit for bit the "
                           f"single run's ({len(bad)} differ{where})")
    check(tail_a == tail_b, f"{label}: every column of the second half identical")
    return names, tail_a


def test_restart(r):
    split_against_single(r, "healthy")


def test_restart_inner(r):
    # A 1 degree pit, 5 um deep, on the inner race (lubricated_defect_inner's): the balls cross
    # it at BPFI (625 Hz at 500 rad/s), about every 1.6 ms, ~6 steps each: about nine crossings
    # in the second half (n_masked > 0; measured 54 steps).
    names, tail = split_against_single(r, "inner", defect="inner", size=1.0)
    j = names.index("n_masked")
    steps = sum(float(row[j]) > 0 for row in tail)
    check(steps > 0, f"inner: the second half crosses the pit ({steps} steps with n_masked > 0)")


if __name__ == "__main__":
    run_named_test({"restart": test_restart, "restart_inner": test_restart_inner},
                   "ohmdem_lub_restart_")

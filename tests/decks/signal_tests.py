#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Deck-level tests of fix signal/table (the bearing deck's signal.txt writer).

  print_equal     every value of signal.txt equals fix print's (15 significant digits, what
                  fix print writes) on the same run: time, the fixes' outputs, R, the sums
  restart_append  a run split by write_restart/read_restart into the same folder gives the
                  single run's signal.txt to the last byte (the second part appends)
  restart_dt      continued with another time step, the time column goes on from the restart
                  point at the new step (not step x dt)

Usage: signal_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import argparse
import os
import tempfile

from bearing_tests import Runner, read_signal
from deck_checks import check, finish


def test_print_equal(r):
    out, _ = r.run("print_equal", tend=0.003, defect="inner", printcheck=1)
    ours = open(os.path.join(out, "signal.txt")).read().splitlines()
    theirs = open(os.path.join(out, "signal_print.txt")).read().splitlines()
    check(ours[0] == theirs[0], "print_equal: same header")
    check(len(ours) == len(theirs) and len(ours) == 3001, f"print_equal: {len(ours) - 1} rows each")
    bad = 0
    for a, b in zip(ours[1:], theirs[1:]):
        va, vb = a.split(), b.split()
        # fix print formats with %.15g: our shortest round-trip value rounded the same way
        bad += len(va) != len(vb) or any(f"{float(x):.15g}" != y for x, y in zip(va, vb))
    check(bad == 0, f"print_equal: every value equal to fix print's to 15 digits ({bad} rows differ)")


def restart_pair(r, name, dt_second):
    full, _ = r.run(f"{name}_full", tend=0.004)
    split = os.path.join(r.workdir, f"{name}_split")
    first, _ = r.run(f"{name}_split", deck=os.path.join(os.path.dirname(__file__),
                                                        "in.restart_first"),
                     bearing_deck=r.deck, tend=0.002)
    # The second part continues into the same folder, from the restart file written there.
    r.run(f"{name}_split", tend=0.004, start="restart", dt=dt_second,
          restart_file=os.path.join(split, "half.restart"))
    return full, split


def test_restart_append(r):
    full, split = restart_pair(r, "append", 1e-6)
    a = open(os.path.join(full, "signal.txt"), "rb").read()
    b = open(os.path.join(split, "signal.txt"), "rb").read()
    na, nb = a.count(b"\n"), b.count(b"\n")
    check(len(a) > 0 and a == b, f"restart_append: split run's signal.txt identical to the single "
                                 f"run's ({nb} vs {na} lines)")


def test_restart_dt(r):
    _, split = restart_pair(r, "dt", 2e-6)
    s = read_signal(split)
    t = s["time"]
    first = t[t <= 0.002 + 1e-12]
    second = t[t > 0.002 + 1e-12]
    check(len(first) == 2000 and abs(first[-1] - 0.002) < 1e-15,
          f"restart_dt: first part ends at t = {first[-1]!r} s after {len(first)} rows")
    steps = second - 0.002
    check(len(second) > 0 and abs(steps[0] - 2e-6) < 1e-15 and
          max(abs(steps[i] - 2e-6 * (i + 1)) for i in range(len(steps))) < 1e-12,
          f"restart_dt: the second part goes on at the new step from 0.002 s "
          f"({len(second)} rows, last t = {second[-1]!r} s)")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test")
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    a = p.parse_args()
    keep = os.environ.get("OHMDEM_KEEP_TEST_DIR")
    with tempfile.TemporaryDirectory(prefix=f"ohmdem_{a.test}_", dir=keep) as wd:
        r = Runner(os.path.abspath(a.exe), os.path.abspath(a.src), wd)
        {"print_equal": lambda: test_print_equal(r),
         "restart_append": lambda: test_restart_append(r),
         "restart_dt": lambda: test_restart_dt(r)}[a.test]()
    finish()


if __name__ == "__main__":
    main()

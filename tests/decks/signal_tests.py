#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Deck-level tests of fix signal/table (the bearing deck's signal.txt writer).

  print_equal     every value of signal.txt equals fix print's (15 significant digits, what
                  fix print writes) on the same run: time, the fixes' outputs, R, the sums
  restart_append  a run split by write_restart/read_restart into the same folder gives the
                  single run's signal.txt to the last byte (the second part appends)
  restart_dt      continued with another time step, the time column goes on from the restart
                  point at the new step (not step x dt)
  npy_equal       -var signal_format npy: numpy.load reads signal.npy as named float64 columns
                  equal, bit for bit, to signal.txt of the same run; ohmdem-post gives the
                  same statistics from both
  npy_restart_append  the split run's signal.npy is the single run's, byte for byte
  loaded_contacts n_contacts_race counts the race contacts that carry a load: at every step
                  it equals the contacts of races.dump with a normal force > 0 (a ball exactly
                  touching its race, fn = 0, carries no current and was counted)

Usage: signal_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import argparse
import json
import os
import subprocess
import tempfile

import numpy as np

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


def restart_pair(r, name, dt_second, **var):
    full, _ = r.run(f"{name}_full", tend=0.004, **var)
    split = os.path.join(r.workdir, f"{name}_split")
    first, _ = r.run(f"{name}_split", deck=os.path.join(os.path.dirname(__file__),
                                                        "in.restart_first"),
                     bearing_deck=r.deck, tend=0.002, **var)
    # The second part continues into the same folder, from the restart file written there.
    # another dt is another parameter: declared (restart_changes yes) when it differs
    changes = {"restart_changes": "yes"} if dt_second != 1e-6 else {}
    r.run(f"{name}_split", tend=0.004, start="restart", dt=dt_second,
          restart_file=os.path.join(split, "half.restart"), **changes, **var)
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
    with open(os.path.join(split, "run.json")) as f:
        changed = json.load(f).get("restart_changes", "")
    check("dt 1e-6 -> 2e-06" in changed, f"restart_dt: run.json records the new step: {changed!r}")


def test_npy_equal(r, post):
    text, _ = r.run("text", tend=0.02, defect="inner")
    binary, _ = r.run("binary", tend=0.02, defect="inner", signal_format="npy")
    a = np.load(os.path.join(binary, "signal.npy"))  # numpy's own reader
    b = np.loadtxt(os.path.join(text, "signal.txt"))
    header = open(os.path.join(text, "signal.txt")).readline().split()[1:]
    check(list(a.dtype.names) == header and all(a.dtype[n] == np.float64 for n in header),
          f"npy_equal: named float64 columns {a.dtype.names[:3]}... = the text header")
    same = a.shape == (b.shape[0],) and all(
        np.array_equal(a[n].view(np.uint64), b[:, i].view(np.uint64)) for i, n in enumerate(header))
    check(same, f"npy_equal: {a.shape[0]} rows equal bit for bit to signal.txt's ({b.shape[0]} rows)")
    def stats(folder, name):
        res = subprocess.run([post, "stats", os.path.join(folder, name), "--from", "0.015"],
                             capture_output=True, text=True)
        check(res.returncode == 0, f"npy_equal: ohmdem-post stats {name} exits 0 ({res.stderr.strip()})")
        return [l for l in res.stdout.splitlines() if not l.startswith("#")]
    st, sb = stats(text, "signal.txt"), stats(binary, "signal.npy")
    check(len(st) > 5 and st == sb, "npy_equal: ohmdem-post stats identical from both files")
    res = subprocess.run([post, "collect", text, binary, "--format", "csv"], capture_output=True,
                         text=True)
    rows = [l.split(",") for l in res.stdout.splitlines() if l and not l.startswith("#")]
    head = rows[0] if rows else []
    keep = [i for i, k in enumerate(head) if k not in ("run", "out")]
    check(res.returncode == 0 and len(rows) == 3 and
          [rows[1][i] for i in keep] == [rows[2][i] for i in keep],
          f"npy_equal: collect finds the signal.npy run and gives it the text run's row "
          f"({res.stderr.strip()})")


def test_npy_restart_append(r):
    full, split = restart_pair(r, "npy", 1e-6, signal_format="npy")
    a = open(os.path.join(full, "signal.npy"), "rb").read()
    b = open(os.path.join(split, "signal.npy"), "rb").read()
    rows = np.load(os.path.join(split, "signal.npy")).shape[0]
    check(len(a) > 0 and a == b and rows == 4000,
          f"npy_restart_append: split run's signal.npy identical to the single run's "
          f"({len(b)} vs {len(a)} bytes, {rows} rows)")


def races_dump_loads(path):
    """{timestep: loaded contacts} of races.dump (f_inner[1] and f_outer[1]: the normal forces,
    columns 6 and 12 of 'id x y vx vy f_inner[1..6] f_outer[1..6]')."""
    counts, step, lines = {}, None, open(path).read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            i += 2
        elif lines[i].startswith("ITEM: ATOMS"):
            i += 1
            n = 0
            while i < len(lines) and not lines[i].startswith("ITEM:"):
                v = lines[i].split()
                n += (float(v[5]) > 0) + (float(v[11]) > 0)
                i += 1
            counts[step] = n
        else:
            i += 1
    return counts


def test_loaded_contacts(r):
    out, _ = r.run("loaded", tend=2e-5, dumpraces=1)
    sig = read_signal(out)
    loads = races_dump_loads(os.path.join(out, "races.dump"))
    steps = [round(t / 1e-6) for t in sig["time"]]
    bad = [(s, int(n), loads.get(s)) for s, n in zip(steps, sig["n_contacts_race"])
           if loads.get(s) != int(n)]
    check(len(steps) == 20 and not bad,
          f"loaded_contacts: n_contacts_race is the loaded contacts of races.dump at every step "
          f"(step, signal, dump where they differ: {bad[:3]})")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test")
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    p.add_argument("--post", default="")
    a = p.parse_args()
    keep = os.environ.get("OHMDEM_KEEP_TEST_DIR")
    with tempfile.TemporaryDirectory(prefix=f"ohmdem_{a.test}_", dir=keep) as wd:
        r = Runner(os.path.abspath(a.exe), os.path.abspath(a.src), wd)
        {"print_equal": lambda: test_print_equal(r),
         "restart_append": lambda: test_restart_append(r),
         "restart_dt": lambda: test_restart_dt(r),
         "npy_equal": lambda: test_npy_equal(r, os.path.abspath(a.post)),
         "npy_restart_append": lambda: test_npy_restart_append(r),
         "loaded_contacts": lambda: test_loaded_contacts(r)}[a.test]()
    finish()


if __name__ == "__main__":
    main()

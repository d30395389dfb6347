#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The outer pit's branch, the second stage after diagnose (studies/locate_outer.py, issue 26).

Parts without runs: the chain read from a record's header repeats the record sample for sample;
the fold comparison (a pulse moved by a fraction of a bin aligns to chi2 ~ its noise, one 10 %
higher does not); the margin rule. Then one run: a 1.5 deg pit 20 deg
from the load direction (the branches 27.7 deg apart: this record's best run of the other branch
has chi2 > 400 against ~130 for its own, studies/locate_outer.py on the same record), acquired at
20 kHz, 16 bits, low noise, located within --zone 25 (two branches); and
the errors of a record not from acquire and of a scene without a radial load.
Usage: locate_outer_tests.py --exe OHMDEM --post OHMDEM_POST --src SOURCE_DIR"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

from deck_checks import check, finish


def data_lines(path):
    with open(path) as f:
        return [line for line in f if not line.startswith("#")]


def chain_repeats(post, lo, tmp):
    """A record's chain, read back from its header, acquires the same samples again."""
    t = np.arange(0, 0.02, 1e-6)
    x = 1.4 + 0.05 * np.sin(2 * np.pi * 937 * t) + 0.3 * (np.sin(2 * np.pi * 211 * t) > 0.99)
    src = os.path.join(tmp, "signal.txt")
    np.savetxt(src, np.c_[t, x], header="time R", comments="# ")
    rec = os.path.join(tmp, "rec.txt")
    subprocess.run([post, "acquire", "--no-metadata", "--column", "R", "--scale", "0.1",
                    "--offset", "0.001", "--from", "0.002", "--lowpass", "8000", "--order", "4",
                    "--rate", "20000", "--noise-density", "1e-7", "--bits", "16", "--range", "0",
                    "0.2", "--seed", "5", "--name", "V", "--unit", "V", "--output", rec, src],
                   check=True)
    args, start, end, name = lo.read_chain(rec)
    check(name == "V" and abs(start - 0.002) < 1e-6 and abs(end - 0.02) < 2e-6,
          f"the record's column and window: {name}, {start}, {end}")
    again = os.path.join(tmp, "again.txt")
    subprocess.run([post, "acquire", "--no-metadata", "--from", repr(start), "--seed", "5"]
                   + args + ["--output", again, src], check=True)
    check(data_lines(again) == data_lines(rec) and len(data_lines(rec)) > 300,
          f"the chain from the header repeats the record's {len(data_lines(rec))} samples")
    bad = os.path.join(tmp, "bad.txt")
    with open(bad, "w") as f:
        f.write("# time V\n0 1\n")
    r = subprocess.run(["/usr/bin/python3", lo.__file__, "--metadata", src, bad,
                        os.path.join(tmp, "o")], capture_output=True, text=True)
    check(r.returncode != 0 and "no '# chain:' line" in r.stderr,
          "a record not from acquire: refused, naming the header line: " + r.stderr.strip())


def folds_compare(fc):
    n = 400
    j = np.arange(n)
    y = 0.2 * np.exp(-0.5 * ((j - n / 4 - 20) / 6.0) ** 2)
    se = np.full(n, 1e-3)
    rng = np.random.default_rng(3)
    rec = (y + rng.normal(0, 1e-3, n), se)
    moved = (0.2 * np.exp(-0.5 * ((j - n / 4 - 20.6) / 6.0) ** 2) + rng.normal(0, 1e-3, n), se)
    higher = (1.1 * y + rng.normal(0, 1e-3, n), se)
    c_moved = fc.chi2_noise(rec, moved, 1.25e-5)
    c_higher = fc.chi2_noise(rec, higher, 1.25e-5)
    # chi2 of two independent noises of se each, over 0.9 n bins in units of sqrt(2) se: ~ 0.9 n;
    # a pulse 10 % higher adds sum (0.1 y)^2 / (2 se^2) (~2100 here), less what the constant takes
    extra = float(np.sum((0.1 * y) ** 2) / (2 * 1e-3 ** 2))
    check(c_moved < 1.5 * 0.9 * n, f"a pulse 0.6 bin later aligns: chi2 {c_moved:.0f} ~ bins")
    check(c_higher > 0.9 * n + 0.7 * extra,
          f"a pulse 10 % higher does not: chi2 {c_higher:.0f} (bins + {extra:.0f})")


def margin_rule(lo):
    placed, note = lo.decide([(350.0, -7.5, -7.5, 1.5, 10), (100.0, 20.2, 20.0, 1.5, 12)],
                             200, 175, 27.69)
    check(placed == 0 and "margin of 250" in note, "a margin of 250 > 200 places: " + note)
    placed, note = lo.decide([(250.0, -7.5, -7.5, 1.5, 10), (100.0, 20.2, 20.0, 1.5, 12)],
                             200, 175, 27.69)
    check(placed is None and "branches at 20.2, -7.5 deg" in note, "150 < 200 does not: " + note)
    placed, note = lo.decide([(9000.0, -7.5, -7.5, 1.5, 10), (5000.0, 20.2, 20.0, 1.5, 12)],
                             200, 175, 27.69)
    check(placed is None and "another scene" in note,
          "no run like the record (28 a bin > 20): not determined: " + note)


def one_record(a, tmp):
    env = dict(os.environ, OHMDEM=a.exe, POST=a.post, OMPI_MCA_ess_singleton_isolated="1")
    sim = os.path.join(tmp, "sim")
    deck = os.path.join(a.src, "inputs", "bearing_6208", "in.bearing")
    subprocess.run([a.exe, "-in", deck, "-var", "out", sim, "-log", os.path.join(tmp, "log"),
                    "-screen", "none", "-var", "defect", "outer", "-var", "size", "1.5", "-var",
                    "load", "radial", "-var", "position", "110", "-var", "depth", "5e-5",
                    "-var", "tend", "0.35", "-var", "tslide", "0.05"],
                   check=True, env=env, cwd=os.path.dirname(deck))
    rec = os.path.join(tmp, "rec.txt")
    subprocess.run([a.post, "acquire", "--column", "R", "--scale", "0.1", "--from", "0.05",
                    "--lowpass", "8000", "--order", "4", "--rate", "20000", "--bits", "16",
                    "--range", "0", "0.1", "--noise-density", "1e-8", "--seed", "7", "--name",
                    "V", "--unit", "V", "--output", rec, os.path.join(sim, "signal.txt")],
                   check=True)
    tool = os.path.join(a.src, "studies", "locate_outer.py")
    r = subprocess.run(["/usr/bin/python3", tool, "--metadata", os.path.join(sim, "run.json"),
                        "--zone", "25", rec, os.path.join(tmp, "out")],
                       capture_output=True, text=True, env=env)
    check(r.returncode == 0, "locate_outer.py runs: " + r.stderr[-600:])
    if r.returncode != 0:
        return
    d = json.loads(r.stdout)
    print(json.dumps({k: d[k] for k in ("position_deg", "note", "candidates")}))
    check(d["branch_determined"] and abs(d["position_deg"] - 20.0) <= 15,
          f"the pit 20 deg from the load placed on its branch: {d['position_deg']}")
    lo_, hi_ = d["position_interval_deg"]
    check(lo_ <= d["position_deg"] <= hi_ and hi_ - lo_ < 10, f"its interval: [{lo_}, {hi_}]")
    check(len(d["candidates"]) == 2 and d["runs_made"] > 4, "two branches searched, with runs")
    with open(os.path.join(tmp, "out", "locate.json")) as f:
        check(json.load(f) == d, "OUT/locate.json holds the printed answer")
    big = [f for _, _, fs in os.walk(os.path.join(tmp, "out")) for f in fs if f == "signal.txt"]
    check(not big, "the runs' 1 MHz signals are gone once acquired")
    meta = os.path.join(tmp, "force.json")
    with open(os.path.join(sim, "run.json")) as f, open(meta, "w") as g:
        m = json.load(f)
        m["load"] = "force"
        json.dump(m, g)
    r = subprocess.run(["/usr/bin/python3", tool, "--metadata", meta, rec,
                        os.path.join(tmp, "out2")], capture_output=True, text=True, env=env)
    check(r.returncode != 0 and "load radial only" in r.stderr,
          "a scene without a radial load: refused: " + r.stderr.strip()[-200:])


def main():
    p = argparse.ArgumentParser()
    for name in ("--exe", "--post", "--src"):  # ohmdem, ohmdem-post, the source tree
        p.add_argument(name, required=True)
    a = p.parse_args()
    a.exe, a.post, a.src = (os.path.abspath(v) for v in (a.exe, a.post, a.src))
    os.environ.update(OHMDEM=a.exe, POST=a.post)
    sys.path.insert(0, os.path.join(a.src, "studies"))
    import fold_compare
    import locate_outer
    with tempfile.TemporaryDirectory() as tmp:
        chain_repeats(a.post, locate_outer, tmp)
        folds_compare(fold_compare)
        margin_rule(locate_outer)
        one_record(a, tmp)
    finish()


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Deck-level tests of how a run ends (doc/run_status.md).

  finished     exit 0; run.json "status": "finished", "time_reached" = tend; no warning about
               the conducting path (the balls start exactly touching)
  restart_geometry  a restart continued with another Nb, Db or race diameter is refused (even with
               restart_changes yes); another speed is refused unless restart_changes yes, and
               run.json then records the change
  conduction_lost  a path lost after it existed is warned at the 1st, 10th, 100th, ...
               evaluation without it
  interrupted  SIGTERM during the run: exit 3; run.json "interrupted" with the time reached
               (the last row of signal.txt); the forced restart file in the run's folder, none
               in the working folder
  failed       unstable settings (dt 2e-5, a ring of 1e-9 kg, a ring damping of 1e9, a density
               of 1): fix bearing/race stops the run naming the cause (exit 1); run.json
               "failed" with the time reached and the error's message; the rows written before
               the failure are kept in
               signal.txt, none of them garbage
  deck_errors  impossible deck variables stop before the run with a message naming the
               variable (exit 1)
  step_counts  a run that cannot reach its tend in one run's steps (dt 1e-20), that takes no
               step (tend below dt, or a restart less than a step before tend), or that writes
               no row (nout beyond the run's steps, fresh or from a restart) stops before it
               starts, naming the variable; signal.txt is not written

Usage: run_status_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import argparse
import json
import os
import signal
import subprocess
import tempfile
import time

import numpy as np

from deck_checks import check, finish, read_signal


def command(a, out, **var):
    os.makedirs(out, exist_ok=True)
    cmd = [a.exe, "-in", os.path.join(a.src, "inputs", "bearing_6208", "in.bearing"),
           "-log", os.path.join(out, "log.txt"), "-screen", "none", "-var", "out", out]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    return cmd


def meta(out):
    with open(os.path.join(out, "run.json")) as f:
        return json.load(f)


def test_finished(a, work):
    out = os.path.join(work, "finished")
    r = subprocess.run(command(a, out, tend=0.002), cwd=work)
    m = meta(out)
    check(r.returncode == 0, f"finished: exit status {r.returncode} (0)")
    check(m["status"] == "finished", f"finished: run.json status {m['status']}")
    check(abs(m["time_reached"] - 0.002) < 1e-12, f"finished: time reached {m['time_reached']}")
    log = open(os.path.join(out, "log.txt"), errors="replace").read()
    # the balls start exactly touching: no current at step 0 is no news
    check("no conducting path" not in log, "finished: no conducting-path warning")


def test_conduction_lost(a, work):
    # two balls and a 200 deg inner pit: at times both contacts are in the pit and no current
    # flows, after it did. Said at the 1st, 10th, 100th, 1000th evaluation without a path.
    out = os.path.join(work, "lost")
    r = subprocess.run(command(a, out, tend=0.03, Nb=2, defect="inner", size=200, position=90),
                       cwd=work)
    log = open(os.path.join(out, "log.txt"), errors="replace").read()
    R = read_signal(os.path.join(out, "signal.txt"))["R"]
    first = int(np.argmax(np.isfinite(R)))
    lost = int(np.sum(~np.isfinite(R[first:])))
    said = [n for n in (1, 10, 100, 1000, 10000) if f"({n} evaluations so far" in log]
    expected = [n for n in (1, 10, 100, 1000, 10000) if n <= lost]
    check(r.returncode == 0, f"conduction_lost: exit status {r.returncode} (0)")
    check(lost > 0 and said == expected,
          f"conduction_lost: {lost} rows without a path after one existed, warned at {said} "
          f"(expected {expected})")


def test_interrupted(a, work):
    out = os.path.join(work, "interrupted")
    p = subprocess.Popen(command(a, out, tend=50), cwd=work)
    # wait until the run writes rows, then interrupt it as a batch system would
    sig = os.path.join(out, "signal.txt")
    for _ in range(600):
        if os.path.exists(sig) and os.path.getsize(sig) > 100000:
            break
        time.sleep(0.1)
    p.send_signal(signal.SIGTERM)
    rc = p.wait(timeout=120)
    m = meta(out)
    t_last = read_signal(sig)["time"][-1]
    check(rc == 3, f"interrupted: exit status {rc} (3)")
    check(m["status"] == "interrupted", f"interrupted: run.json status {m['status']}")
    check(0 < m["time_reached"] < 50 and abs(m["time_reached"] - t_last) < 1e-12,
          f"interrupted: time reached {m['time_reached']} = last row {t_last}")
    forced_out = [f for f in os.listdir(out) if f.startswith("restart_forced_")]
    forced_cwd = [f for f in os.listdir(work) if f.startswith("restart_forced_")]
    check(len(forced_out) == 1 and not forced_cwd,
          f"interrupted: forced restart in the run's folder {forced_out}, none in the working "
          f"folder {forced_cwd}")


def test_failed(a, work):
    # unstable settings the issue tried: each stops with the cause named, nothing garbage in
    # signal.txt (R = inf at t = 0 is physical: the balls start exactly touching)
    cases = [({"dt": 2e-5}, "sqrt(m/k)"),
             ({"Mring": 1e-9, "load": "radial"}, "M = 1e-09 kg"),
             ({"Cring": 1e9, "load": "radial"}, "2M/C"),
             ({"rho": 1}, "m = 1.05e-06 kg"),
             ({"mcage": 1e-9}, "the stiffest critical step, the cage on a ball sqrt(mu/k)")]
    for var, cause in cases:
        name = "_".join(f"{k}{v}" for k, v in var.items())
        out = os.path.join(work, "failed_" + name)
        r = subprocess.run(command(a, out, tend=0.05, **var), cwd=work, capture_output=True,
                           text=True)
        m = meta(out)
        log = open(os.path.join(out, "log.txt"), errors="replace").read()
        path = os.path.join(out, "signal.txt")
        names = open(path).readline().lstrip("#").split()
        data = np.loadtxt(path, ndmin=2).reshape(-1, len(names))
        rows = np.concatenate([[0.0], data[:, 0]])  # the start, then the rows written
        iR = names.index("R")  # R = inf is physical (no contact), NaN never
        garbage = int(np.sum(~np.isfinite(np.delete(data, iR, axis=1)))) + \
            int(np.sum(np.isnan(data[:, iR])))
        check(r.returncode == 1, f"failed {var}: exit status {r.returncode} (1)")
        check("ran away" in log and cause in log,
              f"failed {var}: the run stops saying the contacts ran away and '{cause}'")
        check(m["status"] == "failed", f"failed {var}: run.json status {m['status']}")
        check("ran away" in m.get("error", "") and cause in m.get("error", ""),
              f"failed {var}: run.json's error says why: {m.get('error', '')[:80]!r}...")
        # the step that failed is not written: the last row is the step before it
        dt = var.get("dt", 1e-6)
        check(0 < m["time_reached"] < 0.05 and
              abs(rows[-1] + dt - m["time_reached"]) < 1e-9 * m["time_reached"],
              f"failed {var}: time reached {m['time_reached']}, signal.txt kept up to "
              f"{rows[-1]} ({len(data)} rows)")
        check(garbage == 0, f"failed {var}: no NaN or inf from garbage in signal.txt ({garbage})")


def test_restart_geometry(a, work):
    # a run continued from a restart file with another geometry is refused, naming it
    out = os.path.join(work, "first")
    first = [a.exe, "-in", os.path.join(a.src, "tests", "decks", "in.restart_first"),
             "-var", "bearing_deck", os.path.join(a.src, "inputs", "bearing_6208", "in.bearing"),
             "-var", "out", out, "-var", "tend", "0.001", "-log", "none", "-screen", "none"]
    os.makedirs(out, exist_ok=True)
    check(subprocess.run(first, cwd=work).returncode == 0, "restart_geometry: first half ran")
    restart = os.path.join(out, "half.restart")
    cases = [({"Nb": 12}, "deck variable Nb: 12, but the restart file has 13 balls"),
             ({"Db": 0.0125}, "deck variables Db and rho: a ball of 0.0125 m"),
             # the geometry cannot change even when the change is declared
             ({"Dext": 0.0735, "Dinn": 0.0483, "restart_changes": "yes"},
              "the balls read from the restart file are up to"),
             ({"tend": 0.0005}, "deck variable tend: 0.0005 s lies before the time the run "
                                "starts from, 0.001 s"),
             ({"restart_file": os.path.join(work, "none.restart")},
              "deck variable restart_file: no file"),
             # another operating point: refused unless the change is declared, then recorded
             ({"omega": 600}, "deck variable restart_file: " + restart + ": its run had other "
                              "parameters (the restart's -> this run's): omega_inner 500 -> 600"),
             ({"omega": 600, "restart_changes": "yes"}, None)]
    for var, msg in cases:
        name = "_".join(f"{k}{os.path.basename(str(v))}" for k, v in var.items())
        cont = os.path.join(work, "cont_" + name)
        opts = {"tend": 0.002, "start": "restart", "restart_file": restart, **var}
        r = subprocess.run(command(a, cont, **opts), cwd=work)
        log = open(os.path.join(cont, "log.txt"), errors="replace").read()
        if msg is None:
            changed = meta(cont).get("restart_changes", "")
            check(r.returncode == 0 and "omega_inner 500 -> 600" in changed,
                  f"restart_geometry: {var} continues (exit {r.returncode}), run.json records "
                  f"restart_changes {changed!r}")
        else:
            check(r.returncode == 1 and msg in log,
                  f"restart_geometry: {var} -> exit {r.returncode}, '{msg}' in the log")


def test_deck_errors(a, work):
    cases = [({"dt": 0}, "deck variable dt: the time step must be > 0 s, got 0"),
             ({"tend": -1}, "deck variable tend: the simulated time must be > 0 s, got -1"),
             ({"nout": 0}, "deck variable nout: signal.txt every nout steps needs a whole "
                           "number >= 1, got 0"),
             ({"nout": 2.5}, "deck variable nout"),
             ({"Nb": 12.5}, "deck variable Nb: the number of balls must be a whole number >= 1"),
             ({"Db": 0.013}, "deck variable Db: the balls (0.013 m) do not fit between the races"),
             ({"Dext": 0.04}, "deck variables Dext and Dinn: the outer race diameter must exceed "
                              "the inner one"),
             ({"nthermo": 0}, "deck variable nthermo"),
             ({"restart_every": -1}, "deck variable restart_every: restart files every N steps "
                                     "needs a whole number >= 0 (0: none), got -1"),
             ({"restart_every": 1.5}, "deck variable restart_every")]
    for var, msg in cases:
        out = os.path.join(work, "err_" + "_".join(f"{k}{v}" for k, v in var.items()))
        r = subprocess.run(command(a, out, **var), cwd=work, capture_output=True, text=True)
        log = open(os.path.join(out, "log.txt"), errors="replace").read()
        check(r.returncode == 1 and f"ERROR: {msg}" in log,
              f"deck_errors: {var} -> exit {r.returncode}, '{msg}' in the log")


def test_step_counts(a, work):
    cases = [({"dt": 1e-20}, "deck variable dt: reaching tend = 0.02 s at dt = 1e-20 s takes "
                             "2e+18 steps, more than one run takes (2147483647)"),
             ({"tend": 1e-7}, "deck variable tend: 1e-07 s is below one time step (dt = 1e-6 s)"),
             ({"nout": "1e9"}, "deck variable nout: signal.txt every 1e9 steps, but the run takes "
                               "20000 steps to tend = 0.02 s: no row would be written")]
    first = os.path.join(work, "first")
    r = subprocess.run([a.exe, "-in", os.path.join(a.src, "tests", "decks", "in.restart_first"),
                        "-var", "bearing_deck", os.path.join(a.src, "inputs", "bearing_6208",
                                                             "in.bearing"),
                        "-var", "out", first, "-var", "tend", "0.001", "-log", "none",
                        "-screen", "none"], cwd=work)
    check(r.returncode == 0, "step_counts: the first half of a restart")
    restart = {"start": "restart", "restart_file": os.path.join(first, "half.restart"),
               "restart_changes": "yes"}
    cases += [({**restart, "tend": 0.0010000004},
               "deck variable tend: 0.0010000004 s is less than one time step (dt = 1e-6 s) after "
               "the time the run starts from, 0.001 s"),
              # steps 1000 to 1500: no multiple of 800 (fix signal/table writes at those)
              ({**restart, "tend": 0.0015, "nout": 800},
               "deck variable nout: signal.txt every 800 steps, but the 500 steps from the "
               "restart point to tend = 0.0015 s write no row")]
    for var, msg in cases:
        out = os.path.join(work, "err_" + "_".join(f"{k}{os.path.basename(str(v))}"
                                                   for k, v in var.items()))
        r = subprocess.run(command(a, out, **var), cwd=work, capture_output=True, text=True)
        log = open(os.path.join(out, "log.txt"), errors="replace").read()
        check(r.returncode == 1 and f"ERROR: {msg}" in log and
              not os.path.exists(os.path.join(out, "signal.txt")),
              f"step_counts: {var} -> exit {r.returncode}, '{msg}' in the log, no signal.txt")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test")
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    a = p.parse_args()
    with tempfile.TemporaryDirectory(prefix=f"run_status_{a.test}_") as work:
        globals()[f"test_{a.test}"](a, work)
    finish()


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The output folder and the restart file of the bearing deck (issue: nothing lost, a
newcomer's first hour; doc/command_deck_files.md).

  nested        -var out results/healthy in a folder where results/ does not exist (a fresh
                clone), and the deck with no -var at all (out/bearing): made with the parents
  lock          a second run into the folder of a live run stops (exit 1) naming the holder's
                pid; after the holder is killed (SIGKILL) its lock is stale: the next run
                replaces it with a warning and finishes
  restart_cut   a restart file cut at 8..200 bytes and in its atoms, or damaged in the middle
                (a fix's section, a ball outside the box), stops with one message naming the
                file (exit 1, at once: read_restart alone loops on a cut header); the whole
                file still continues
  sliding       run.json's t_sliding_end for the bearing that ran (the 6203's after its sliding),
                and the settle time of load fixed (tsettle) likewise
  long_path     an output path over PATH_MAX, and a component over NAME_MAX, stop with a
                message (exit 1), not an abort inside LIGGGHTS (exit 134)
  out_blank     -var out with a blank stops before the folder and its lock are made
  lock_wait     a lock whose holder ends within a second or two (a run just stopped with
                SIGTERM, one of its processes still ending): the next run waits for it and
                takes the folder, instead of refusing it

Usage: run_folder_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import argparse
import json
import os
import re
import signal
import subprocess
import tempfile
import time

from deck_checks import check, finish


def deck(a, *var):
    return [a.exe, "-in", os.path.join(a.src, "inputs", "bearing_6208", "in.bearing"),
            "-log", "none"] + list(var)


def run(cmd, work, timeout=120):
    return subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, errors="replace", timeout=timeout)


def test_nested(a, work):
    r = run(deck(a, "-var", "out", "results/healthy", "-var", "tend", "1e-5"), work)
    check(r.returncode == 0 and os.path.isfile(os.path.join(work, "results/healthy/signal.txt")),
          f"nested: -var out results/healthy: exit {r.returncode}")
    bare = os.path.join(work, "bare")
    os.makedirs(bare)
    r = run(deck(a, "-var", "tend", "1e-5"), bare)  # tend only to keep it short
    check(r.returncode == 0 and os.path.isfile(os.path.join(bare, "out/bearing/run.json")),
          f"nested: no -var out: out/bearing made, exit {r.returncode}")
    check(not os.path.exists(os.path.join(work, "results/healthy/.ohmdem.lock")),
          "nested: the lock is removed after the run")
    # the version of --version in run.json and in the log
    version = subprocess.run([a.exe, "--version"], capture_output=True, text=True).stdout.split()[1]
    with open(os.path.join(work, "results/healthy/run.json")) as f:
        meta = json.load(f)
    check(meta.get("ohmdem_version") == version, f"nested: run.json ohmdem_version "
          f"{meta.get('ohmdem_version')} = --version {version}")
    check(f"ohmdem {version}" in r.stdout, "nested: the screen and log name the version")


def test_lock(a, work):
    holder = subprocess.Popen(deck(a, "-var", "out", "shared", "-var", "tend", "5",
                                   "-screen", "none"), cwd=work)
    try:
        lock = os.path.join(work, "shared", ".ohmdem.lock")
        meta = os.path.join(work, "shared", "run.json")
        for _ in range(200):
            if os.path.exists(lock) and os.path.exists(meta):
                break
            time.sleep(0.05)
        check(os.path.exists(lock), "lock: the live run holds shared/.ohmdem.lock")
        r = run(deck(a, "-var", "out", "shared", "-var", "tend", "1e-5"), work)
        check(r.returncode == 1 and f"in use by the live run of pid {holder.pid}" in r.stdout,
              f"lock: a second run refused, naming pid {holder.pid} (exit {r.returncode}): "
              f"{[l for l in r.stdout.splitlines() if 'ERROR' in l]}")
        # the refused run leaves the holder's run.json alone (it is not its run that failed)
        with open(os.path.join(work, "shared", "run.json")) as f:
            status = json.load(f)["status"]
        check(status == "running", f"lock: the holder's run.json still says running ({status})")
    finally:
        holder.send_signal(signal.SIGKILL)
        holder.wait()
    r = run(deck(a, "-var", "out", "shared", "-var", "tend", "1e-5"), work)
    check(r.returncode == 0 and "stale lock" in r.stdout,
          f"lock: after SIGKILL the stale lock is replaced with a warning (exit {r.returncode})")


def test_restart_cut(a, work):
    first = os.path.join(work, "first")
    r = run([a.exe, "-in", os.path.join(a.src, "tests", "decks", "in.restart_first"),
             "-var", "bearing_deck", os.path.join(a.src, "inputs", "bearing_6208", "in.bearing"),
             "-var", "here", os.path.join(a.src, "inputs", "bearing_6208"),
             "-var", "out", first, "-var", "tend", "2e-5", "-screen", "none"], work)
    whole = open(os.path.join(first, "half.restart"), "rb").read()
    check(r.returncode == 0 and len(whole) > 1000, f"restart_cut: a restart of {len(whole)} bytes")
    for n in (8, 9, 64, 100, 150, 200, len(whole) // 2, len(whole) - 8):
        cut = os.path.join(work, f"cut_{n}.restart")
        with open(cut, "wb") as f:
            f.write(whole[:n])
        t0 = time.time()
        r = run(deck(a, "-var", "out", f"r{n}", "-var", "start", "restart",
                     "-var", "restart_file", cut, "-var", "tend", "4e-5"), work, timeout=60)
        errors = [l for l in r.stdout.splitlines() if "ERROR" in l]
        check(r.returncode == 1 and len(errors) == 1 and cut in errors[0]
              and time.time() - t0 < 30 and len(r.stdout) < 20000,
              f"restart_cut: {n} bytes: one message naming the file (exit {r.returncode}): "
              f"{errors[:2]}")
    # Damage in the middle, the length whole: the fix signal/table's state size, the first
    # ball's y moved far outside the box (read_restart: "Did not assign all atoms correctly").
    import struct
    at = whole.index(b"signal/table\0") + 13
    # one process: the atoms are the last chunk, an int N then N doubles (count, x, y, z, ...)
    start = next(p for p in range(len(whole) - 12, 0, -4)
                 if struct.unpack_from("<i", whole, p)[0] * 8 == len(whole) - p - 4)
    y = start + 4 + 8 * 2
    for label, damaged, want in (
            ("fix state size", whole[:at] + struct.pack("<i", 4000) + whole[at + 4:],
             "fixes' sections are damaged"),
            ("a ball outside the box", whole[:y] + struct.pack("<d", 50.0) + whole[y + 8:],
             "atom 1 lies outside the box")):
        bad = os.path.join(work, "mid.restart")
        with open(bad, "wb") as f:
            f.write(damaged)
        r = run(deck(a, "-var", "out", "mid", "-var", "start", "restart",
                     "-var", "restart_file", bad, "-var", "tend", "4e-5"), work, timeout=60)
        errors = [l for l in r.stdout.splitlines() if "ERROR" in l]
        check(r.returncode == 1 and len(errors) == 1 and bad in errors[0] and want in errors[0],
              f"restart_cut: {label} damaged: one message naming the file (exit {r.returncode})"
              f": {errors[:2]}")
    r = run(deck(a, "-var", "out", "whole", "-var", "start", "restart", "-var", "restart_file",
                 os.path.join(first, "half.restart"), "-var", "tend", "4e-5"), work)
    check(r.returncode == 0, f"restart_cut: the whole file continues (exit {r.returncode})")


def test_long_path(a, work):
    for label, out in (("PATH_MAX", "d/" * 2100), ("NAME_MAX", "x" * 300)):
        r = run(deck(a, "-var", "out", out, "-var", "tend", "1e-5"), work)
        check(r.returncode == 1 and "deck variable out" in r.stdout and label in r.stdout,
              f"long_path: {label}: a message naming out (exit {r.returncode})")


def test_sliding(a, work):
    """run.json's t_sliding_end follows the bearing: after the measured end of sliding (the
    ball set's speed within 0.1 % of its rolling value for good), and within twice it; the
    6208's stays 0.015 s."""
    import numpy as np
    r = run(deck(a, "-var", "out", "s6208", "-var", "tend", "1e-5"), work)
    with open(os.path.join(work, "s6208", "run.json")) as f:
        check(json.load(f)["t_sliding_end"] == 0.015, "sliding: the 6208's t_sliding_end 0.015")
    r = run(deck(a, "-var", "out", "s6203", "-var", "bearing", "6203", "-var", "tend", "0.012",
                 "-screen", "none"), work)
    with open(os.path.join(work, "s6203", "run.json")) as f:
        t_json = json.load(f)["t_sliding_end"]
    path = os.path.join(work, "s6203", "signal.txt")
    with open(path) as f:
        names = f.readline().lstrip("#").split()
    sig = np.loadtxt(path)
    w, t = sig[:, names.index("omega_balls")], sig[:, names.index("time")]
    rolling = np.median(w[t > 0.007])
    t_meas = t[np.nonzero(abs(w - rolling) > 1e-3 * rolling)[0][-1]]
    check(r.returncode == 0 and t_meas < t_json < 2 * t_meas,
          f"sliding: the 6203 slides until {t_meas:.4f} s; t_sliding_end {t_json:.4f} s after it "
          f"and within twice it")
    # load fixed: the ring is held from tsettle on, after the sliding (the 6208's 0.014 s
    # exactly; the 6203's after its sliding, within twice it). The echo shows the fix as run.
    for bearing, low, high in (("machado2014", 0.014, 0.014), ("6203", t_meas, 2 * t_meas)):
        r = run(deck(a, "-var", "out", f"settle_{bearing}", "-var", "bearing", bearing,
                     "-var", "load", "fixed", "-var", "tend", "1e-5", "-echo", "screen"), work)
        fixes = re.findall(r"^fix outer .* settle ([0-9.e+-]+) direction", r.stdout, re.M)
        settle = float(fixes[-1]) if fixes else float("nan")
        check(r.returncode == 0 and low <= settle <= high,
              f"sliding: {bearing} load fixed: tsettle {settle} s in [{low:.4f}, {high:.4f}]")


def test_out_blank(a, work):
    """-var out with a blank broke fix signal/table's arguments after the folder and its lock
    were made: refused first, nothing made, and the next run into the folder needs no
    stale-lock removal."""
    r = run(deck(a, "-var", "out", "with blank", "-var", "tend", "2e-6"), work)
    made = sorted(os.listdir(work))
    check(r.returncode == 1 and "ERROR: deck variable out: expected a folder without blanks" in
          r.stdout and made == [],
          f"out_blank: exit {r.returncode}, the variable and its form named, nothing made {made}")


def test_lock_wait(a, work):
    import socket
    import time
    folder = os.path.join(work, "held")
    os.makedirs(folder)
    import threading
    ending = subprocess.Popen(["sleep", "1.5"])
    threading.Thread(target=ending.wait).start()  # reaped when it ends, as mpirun reaps a rank
    with open(os.path.join(folder, ".ohmdem.lock"), "w") as f:
        f.write(f"pid {ending.pid} host {socket.gethostname()}\n")
    t0 = time.time()
    r = run(deck(a, "-var", "out", folder, "-var", "tend", "2e-6"), work)
    waited = time.time() - t0
    ending.wait()
    check(r.returncode == 0 and "removed the stale lock" in r.stdout and waited > 1.0,
          f"lock_wait: the run waited {waited:.1f} s for the ending holder and took the folder "
          f"(exit {r.returncode}): {[l for l in r.stdout.splitlines() if 'ERROR' in l][:1]}")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test", choices=["nested", "lock", "restart_cut", "long_path", "sliding",
                                    "out_blank", "lock_wait"])
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    a = p.parse_args()
    with tempfile.TemporaryDirectory(prefix=f"runfolder_{a.test}_") as work:
        globals()[f"test_{a.test}"](a, work)
    finish()


if __name__ == "__main__":
    main()

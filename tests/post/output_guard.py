#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""What `ohmdem-post --output FILE` must never do: overwrite what it reads, or leave an empty or
cut file behind.

  inputs  --output (or diagnose --pulse-fold-out) naming one of the inputs (the signal, a hard
          link or a symbolic link to it, the run.json beside it, a --metadata or --baseline file,
          a run of collect) is refused by every command that writes, with one ERROR line, and
          the file is left unchanged.
  full    a write that fails (/dev/full: ENOSPC; a file size limit, RLIMIT_FSIZE: EFBIG, as a
          disk that fills up) exits 1 with one ERROR line naming the file and the system's
          reason, and leaves no file (or the file that was there before, unchanged).

usage: output_guard.py inputs|full --post OHMDEM_POST
"""
import argparse
import json
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    return not ok


def run_folder(work, name):
    d = os.path.join(work, name)
    os.makedirs(d)
    with open(os.path.join(d, "signal.txt"), "w") as f:
        f.write("# time R\n")
        for i in range(2000):
            f.write(f"{i * 1e-4!r} {1.38 + 0.01 * ((i * 7919) % 13)!r}\n")
    with open(os.path.join(d, "run.json"), "w") as f:
        json.dump({"bearing": "machado2014", "omega_inner": 500, "nb": 13, "db": 0.0126,
                   "dp": 0.0606, "defect": "none", "t_sliding_end": 0.0,
                   "status": "finished"}, f)
    return d


def inputs(a, work):
    failed = False
    run = run_folder(work, "run")
    sig = os.path.join(run, "signal.txt")
    meta = os.path.join(run, "run.json")
    os.link(sig, os.path.join(work, "hard.txt"))
    os.symlink(sig, os.path.join(work, "soft.txt"))
    base = shutil.copy(sig, os.path.join(work, "baseline.txt"))
    bearing = ["--bearing", "machado2014", "--omega", "500"]
    cases = [
        ("stats, the signal", ["stats", sig], sig),
        ("stats, a hard link to it", ["stats", sig], os.path.join(work, "hard.txt")),
        ("spectrum, a symbolic link to it", ["spectrum", sig], os.path.join(work, "soft.txt")),
        ("envelope, the run.json beside it", ["envelope", sig, "--band", "100", "2000"], meta),
        ("diagnose, its --baseline", ["diagnose", sig, "--baseline", base] + bearing, base),
        ("orders, the signal", ["orders", sig, "--omega", "500"], sig),
        ("acquire, the signal", ["acquire", sig], sig),
        ("frequencies, its --metadata", ["frequencies", "--metadata", meta], meta),
        ("collect, a run's signal", ["collect", run], sig),
        ("plot, the signal", ["plot", "--kind", "signal", sig], sig),
        ("diagnose --pulse-fold-out, the signal", ["diagnose", sig, "--assume-defect", "outer"]
         + bearing, sig, "--pulse-fold-out"),
    ]
    for what, args, output, *option in cases:
        option = option[0] if option else "--output"
        before = {p: open(p, "rb").read() for p in (sig, meta, base)}
        r = subprocess.run([a.post] + args + [option, output], capture_output=True, text=True)
        lines = [ln for ln in r.stderr.splitlines() if ln.startswith("ERROR")]
        failed |= check(r.returncode == 1 and len(lines) == 1
                        and "is one of the inputs" in lines[0] and f"{option} {output}" in lines[0],
                        f"{what}: refused: {' | '.join(lines) or r.stderr.strip()}")
        failed |= check(all(open(p, "rb").read() == b for p, b in before.items()),
                        f"{what}: the inputs are unchanged")
    # another file is written as before, also over an older one
    out = os.path.join(work, "stats.txt")
    for what in ("a new file", "an existing file"):
        r = subprocess.run([a.post, "stats", sig, "--output", out], capture_output=True,
                           text=True)
        failed |= check(r.returncode == 0 and "rms" in open(out).read(),
                        f"stats --output {what}: written ({r.stderr.strip()})")
    return failed


def no_core_and_limit(size):
    def limit():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write past the limit fails with EFBIG
        resource.setrlimit(resource.RLIMIT_FSIZE, (size, size))
    return limit


def full(a, work):
    failed = False
    sig = os.path.join(run_folder(work, "run"), "signal.txt")
    commands = [("stats", ["stats", sig, "--window-length", "0.001"]),
                ("spectrum", ["spectrum", sig, "--bins"]),
                ("acquire", ["acquire", sig])]
    for name, args in commands:
        # a full disk
        r = subprocess.run([a.post] + args + ["--output", "/dev/full"], capture_output=True,
                           text=True)
        lines = r.stderr.strip().splitlines()
        failed |= check(r.returncode == 1 and len(lines) == 1
                        and lines[0].startswith("ERROR: writing '/dev/full' failed")
                        and "No space left on device" in lines[0],
                        f"{name} --output /dev/full: one error with the reason: {r.stderr.strip()}")
        # a file that cannot grow past 1 kB: nothing left where there was nothing
        out = os.path.join(work, name + ".out")
        r = subprocess.run([a.post] + args + ["--output", out], capture_output=True, text=True,
                           preexec_fn=no_core_and_limit(1024))
        lines = r.stderr.strip().splitlines()
        failed |= check(r.returncode == 1 and len(lines) == 1
                        and lines[0].startswith(f"ERROR: writing '{out}' failed")
                        and "File too large" in lines[0],
                        f"{name}: a failed write, one error with the reason: {r.stderr.strip()}")
        left = [n for n in os.listdir(work) if n.startswith(name + ".out")
                or n.startswith("." + name + ".out")]
        failed |= check(not left, f"{name}: no file left by the failed write {left}")
        # and a file written before is kept as it was
        with open(out, "w") as f:
            f.write("written before\n")
        r = subprocess.run([a.post] + args + ["--output", out], capture_output=True, text=True,
                           preexec_fn=no_core_and_limit(1024))
        failed |= check(r.returncode == 1 and open(out).read() == "written before\n",
                        f"{name}: the file written before is unchanged")
        os.remove(out)
    return failed


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("test", choices=["inputs", "full"])
    ap.add_argument("--post", required=True)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="output_guard_") as work:
        failed = {"inputs": inputs, "full": full}[a.test](a, work)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

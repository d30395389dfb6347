#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The partition sweep (inputs/bearing_6208/in.sweep): folders, identical signals whatever
runs the case, resume after a kill (only the cases finished with the same parameters are
skipped), per-case logs, and a bad case failing alone.
Usage: sweep_tests.py --exe OHMDEM --src SOURCE_DIR"""
import argparse
import hashlib
import os
import subprocess
import tempfile

from deck_checks import check, finish

def digest(path):
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    p.add_argument("--post", required=True)
    a = p.parse_args()
    exe = os.path.abspath(a.exe)
    deck = os.path.join(os.path.abspath(a.src), "inputs", "bearing_6208")
    mpi = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2"]

    def sweep(wd, root, *extra):
        cmd = mpi + [exe, "-partition", "2x1", "-in", os.path.join(deck, "in.sweep"),
                     "-var", "here", deck, "-var", "bearing_deck", os.path.join(deck, "in.bearing"),
                     "-var", "root", root, "-var", "tend", "0.003", *extra]
        res = subprocess.run(cmd, cwd=wd, capture_output=True, text=True)
        return res.returncode, res.stdout + res.stderr

    with tempfile.TemporaryDirectory(prefix="ohmdem_sweep_") as wd:
        root = os.path.join(wd, "sweep")
        rc, out = sweep(wd, root)
        cases = ["0.5", "1.0", "2.0", "3.0"]
        folders = [os.path.join(root, f"size_{c}") for c in cases]
        check(rc == 0 and all(os.path.exists(os.path.join(f, "signal.txt")) for f in folders),
              "2-partition sweep: one folder with signal.txt per case")
        check("sweep: 4/4 cases done" in out, "progress announced on the terminal (k/N done)")
        csv = os.path.join(wd, "collected.csv")
        res = subprocess.run([a.post, "collect", "--format", "csv", "--from", "0.001",
                              "--output", csv] + folders, capture_output=True, text=True)
        rows = [l for l in open(csv).read().splitlines() if l and not l.startswith("#")] \
            if res.returncode == 0 else []
        header = rows[0].split(",") if rows else []
        sizes = sorted(float(r.split(",")[header.index("size_deg")]) for r in rows[1:]) \
            if "size_deg" in header else []
        check(len(rows) == 5 and sizes == [0.5, 1.0, 2.0, 3.0],
              f"ohmdem-post collect: one row per case with its size ({len(rows) - 1} rows) "
              f"{res.stderr.strip()}")

        # The same case alone, and with 2 MPI processes, gives the identical signal.
        for name, cmd in (("alone", [exe]), ("2 processes", mpi + [exe])):
            out_dir = os.path.join(wd, name.replace(" ", "_"))
            subprocess.run(cmd + ["-in", os.path.join(deck, "in.bearing"), "-var", "out", out_dir,
                                  "-var", "defect", "inner", "-var", "size", "1.0",
                                  "-var", "tend", "0.003", "-log", "none", "-screen", "none"],
                           cwd=wd, check=True, capture_output=True)
            check(digest(os.path.join(out_dir, "signal.txt")) ==
                  digest(os.path.join(root, "size_1.0", "signal.txt")),
                  f"case size=1.0: the signal {name} is identical to the sweep's")

        # Resume: a killed case (no 'done' mark) runs again; finished ones are left untouched.
        before = {f: digest(os.path.join(f, "signal.txt")) for f in folders}
        stamps = {f: os.stat(os.path.join(f, "signal.txt")).st_mtime_ns for f in folders}
        killed = folders[2]
        os.remove(os.path.join(killed, "run.done.json"))  # what a kill leaves: no done mark,
        with open(os.path.join(killed, "signal.txt"), "w") as fh:
            fh.write("# time\n0.0\n")  # and a truncated file
        rc, out = sweep(wd, root)
        untouched = all(os.stat(os.path.join(f, "signal.txt")).st_mtime_ns == stamps[f]
                        for f in folders if f != killed)
        check(rc == 0 and untouched, "resume: finished cases skipped, their files untouched")
        check(out.count("already finished with the same parameters: skipped") == 3,
              "resume: the three finished cases said skipped")
        check(digest(os.path.join(killed, "signal.txt")) == before[killed],
              "resume: the killed case ran again and gives the same signal")
        check(all(os.path.exists(os.path.join(f, "log.liggghts")) for f in folders),
              "each case logs into its own folder")

        # Other parameters into the same root: every case runs again.
        rc, out = sweep(wd, root, "-var", "F", "400")
        rerun = all(os.stat(os.path.join(f, "signal.txt")).st_mtime_ns != stamps[f]
                    for f in folders if f != killed)
        check(rc == 0 and rerun and out.count("finished before with other parameters") == 4,
              "another F into the same root: the four cases run again, said so")

        # A bad case fails alone.
        root2 = os.path.join(wd, "bad")
        rc, out = sweep(wd, root2, "-var", "sizes", "1.0 40 2.0", "-var", "ncases", "3")
        check(rc == 0 and "size=40 FAILED" in out, "an impossible size fails with a message")
        check(all(os.path.exists(os.path.join(root2, f"size_{c}", "signal.txt"))
                  for c in ("1.0", "2.0")), "the other cases still finish")
    finish()


if __name__ == "__main__":
    main()

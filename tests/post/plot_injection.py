#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""`ohmdem-post plot` runs nothing that a string of its figure holds: a --title, a --unit (the
axis label) and a run folder's name (the default title) with newlines and gnuplot `system`
commands after them draw the figure with the text shown, and the commands do not run (no marker
file appears; the script gnuplot read has no line of its own for them). An --output name with a
newline is refused before anything is written. Needs gnuplot (exit 77 without it).

usage: plot_injection.py --post OHMDEM_POST
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    return not ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--post", required=True)
    a = ap.parse_args()
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        print("SKIPPED: gnuplot not installed (Debian package gnuplot-nox)")
        return 77
    failed = False
    with tempfile.TemporaryDirectory(prefix="plot_injection_") as work:
        # gnuplot through a wrapper that keeps the script it was given
        wrapper = os.path.join(work, "gnuplot")
        with open(wrapper, "w") as f:
            f.write(f"#!/bin/sh\ncp \"$1\" '{work}/kept.gp'\nexec '{gnuplot}' \"$@\"\n")
        os.chmod(wrapper, 0o755)
        env = dict(os.environ, OHMDEM_GNUPLOT=wrapper)

        def payload(marker):
            return f'\nsystem "touch {marker}"\r\n#'  # relative: ohmdem-post runs in work

        def plot(args, signal, png):
            kept = os.path.join(work, "kept.gp")
            if os.path.exists(kept):
                os.remove(kept)
            r = subprocess.run([a.post, "plot", "--kind", "signal", "--output", png, signal] + args,
                               env=env, cwd=work, capture_output=True, text=True)
            script = open(kept).read() if os.path.exists(kept) else ""
            return r, script

        def signal_in(folder):
            os.makedirs(folder)
            path = os.path.join(folder, "signal.txt")
            with open(path, "w") as f:
                f.write("# time R\n")
                for i in range(200):
                    f.write(f"{i * 1e-4!r} {1.38 + 0.01 * (i % 7)!r}\n")
            return path

        plain = signal_in(os.path.join(work, "plain"))
        cases = [("--title", ["--title", "a title" + payload("title_ran")], plain, "title_ran"),
                 ("--unit", ["--unit", "ohm" + payload("unit_ran")], plain, "unit_ran")]
        # a run folder (someone else's archive) whose name holds the commands
        run = os.path.join(work, "run" + payload("folder_ran"))
        sig = signal_in(run)
        with open(os.path.join(run, "run.json"), "w") as f:
            json.dump({"defect": "none", "status": "finished"}, f)
        cases.append(("a run folder's name", [], sig, "folder_ran"))
        for what, args, signal, marker in cases:
            png = os.path.join(work, marker + ".png")
            r, script = plot(args, signal, png)
            failed |= check(r.returncode == 0 and os.path.getsize(png) > 0,
                            f"{what}: the figure is drawn (exit {r.returncode}) {r.stderr.strip()}")
            failed |= check(not os.path.exists(os.path.join(work, marker)),
                            f"{what}: the system command did not run")
            lines = [ln for ln in script.splitlines() if ln.lstrip().startswith("system")]
            failed |= check(script != "" and not lines,
                            f"{what}: no command line of its own in the script {lines}")
            failed |= check('\\nsystem "touch' in script,
                            f"{what}: the text shows its newline as \\n")
        # an image name with a newline: refused, nothing written
        png = os.path.join(work, 'x\nsystem "touch out_ran"\n.png')
        r, script = plot([], plain, png)
        failed |= check(r.returncode == 1 and "holds a control character" in r.stderr
                        and r.stderr.startswith("ERROR: "),
                        f"--output with a newline: refused: {r.stderr.strip()}")
        failed |= check(script == "" and not any(n.startswith("x") or n.startswith(".x")
                                                 for n in os.listdir(work)),
                        "--output with a newline: gnuplot not started, no file left")
        failed |= check(not os.path.exists(os.path.join(work, "out_ran")),
                        "--output with a newline: the system command did not run")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

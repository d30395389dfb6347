#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""A newcomer's first hour with ohmdem-post: what the figures, the help and the messages show.

  plot_script     what `plot` asks gnuplot to draw (its script, kept by a wrapper given as
                  OHMDEM_GNUPLOT): the title names the run folder (and its defect) when the
                  signal is a run's; the labels of the defect lines stand above the graph, close
                  ones (3xBPFO 20 Hz beside 2xBPFI) in different rows
  plot_floor      a simulated healthy R at the numerical floor (3e-7 of its mean): its signal
                  figure's ticks get the digits that tell them apart, its spectra are drawn up
                  to 1e-5 of the mean (not autoscaled into lines) and say so; a defect's
                  spectrum (spread 1e-2) is autoscaled
  diagnose_floor  `diagnose` of a simulated healthy R at the numerical floor (3e-7 of its mean,
                  one 2e-5 ohm blip: kurtosis in the thousands) says so and reads healthy; a
                  signal with a defect's spread (1e-2) gets no such line
  help_examples   every bearing the commands' --help names as an example is a catalog bearing
                  (`frequencies --bearing NAME` accepts it)
  baseline_rate   a --baseline at another rate than the record: the acquire command the error
                  suggests runs as written, and diagnose then runs with what it says (a baseline
                  faster than the record, text and time-stamped; a record faster than the
                  baseline)

Usage: newcomer_tests.py TEST --post OHMDEM_POST
"""
import argparse
import json
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile


def run_folder(work, name, values, defect="none"):
    """A run folder as the deck writes it: signal.txt (20 kHz) and run.json (the 6208)."""
    run = os.path.join(work, name)
    os.makedirs(run)
    with open(os.path.join(run, "signal.txt"), "w") as f:
        f.write("# time R\n")
        for i, v in enumerate(values):
            f.write(f"{i / 20000!r} {v!r}\n")
    with open(os.path.join(run, "run.json"), "w") as f:
        json.dump({"bearing": "machado2014", "omega_inner": 500, "nb": 13, "db": 0.0126,
                   "dp": 0.0606, "defect": defect, "t_sliding_end": 0.0,
                   "status": "finished"}, f)
    return os.path.join(run, "signal.txt")


def diagnose_floor(a, work):
    import random
    rng = random.Random(1)
    # as the healthy demo run: R = 1.3838 ohm varying smoothly by 4e-7 ohm (no white noise: a
    # simulation), one blip of 2e-5 ohm
    healthy = [1.3838 + 4e-7 * math.sin(2 * math.pi * 31.5 * i / 20000)
               + 1e-7 * math.sin(2 * math.pi * 79.6 * i / 20000) for i in range(4000)]
    healthy[2000] += 2e-5
    failed = False
    r = subprocess.run([a.post, "diagnose", run_folder(work, "healthy", healthy)],
                       capture_output=True, text=True)
    ok = (r.returncode == 0 and re.search(r"^floor: +R varies by [0-9.e-]+ of its mean", r.stdout,
                                          re.M) is not None
          and re.search(r"^verdict: +healthy", r.stdout, re.M) is not None)
    print(("ok   " if ok else "FAIL ") + "healthy run at the numerical floor: said, verdict "
          f"healthy (exit {r.returncode}): "
          f"{[l for l in r.stdout.splitlines() if l.startswith(('floor', 'verdict'))]}")
    failed |= not ok
    r = subprocess.run([a.post, "diagnose", "--format", "json",
                        os.path.join(work, "healthy", "signal.txt")], capture_output=True, text=True)
    floor = json.loads(r.stdout).get("numerical_floor") if r.returncode == 0 else None
    ok = isinstance(floor, str) and "numerical floor" in floor
    print(("ok   " if ok else "FAIL ") + f"the JSON carries it: numerical_floor = {floor!r}")
    failed |= not ok
    noisy = [1.3838 * (1 + 1e-2 * rng.gauss(0, 1)) for _ in range(4000)]
    r = subprocess.run([a.post, "diagnose", run_folder(work, "noisy", noisy)],
                       capture_output=True, text=True)
    ok = r.returncode == 0 and "floor:" not in r.stdout
    print(("ok   " if ok else "FAIL ") + "a spread of 1e-2: no floor line")
    failed |= not ok
    return 1 if failed else 0


def plot_script(a, work):
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        print("SKIPPED: gnuplot not installed (Debian package gnuplot-nox)")
        return 77
    failed = False
    if True:
        run = os.path.join(work, "inner_defect")
        os.makedirs(run)
        # 0.1 s at 20 kHz of pulses at BPFI of the 6208 at 500 rad/s (624.8 Hz)
        with open(os.path.join(run, "signal.txt"), "w") as f:
            f.write("# time R\n")
            for i in range(2000):
                t = i / 20000
                f.write(f"{t!r} {1.38 + 0.1 * (math.sin(2 * math.pi * 624.8 * t) > 0.95)!r}\n")
        with open(os.path.join(run, "run.json"), "w") as f:
            json.dump({"bearing": "machado2014", "omega_inner": 500, "nb": 13, "db": 0.0126,
                       "dp": 0.0606, "defect": "inner", "t_sliding_end": 0.0,
                       "status": "finished"}, f)
        wrapper = os.path.join(work, "gnuplot")
        with open(wrapper, "w") as f:
            f.write(f"#!/bin/sh\ncp \"$1\" {work}/kept.gp\nexec {gnuplot} \"$@\"\n")
        os.chmod(wrapper, 0o755)
        env = dict(os.environ, OHMDEM_GNUPLOT=wrapper)
        r = subprocess.run([a.post, "plot", "--kind", "spectrum", "--output",
                            os.path.join(work, "s.png"), os.path.join(run, "signal.txt")],
                           env=env, capture_output=True, text=True)
        script = open(os.path.join(work, "kept.gp")).read() if r.returncode == 0 else ""
        title = re.search(r"^set title '(.*)'$", script, re.M)
        ok = title is not None and title.group(1).startswith("run inner_defect (inner defect): ")
        print(("ok   " if ok else "FAIL ") + f"the title names the run: "
              f"{title.group(1) if title else r.stderr.strip()}")
        failed |= not ok
        heights = {m.group(1): float(m.group(2)) for m in re.finditer(
            r"^set label \d+ '([^']+)' at first [^,]+, screen ([0-9.]+) rotate by 90 left",
            script, re.M)}
        top = re.search(r"^set tmargin at screen ([0-9.]+)$", script, re.M)
        ok = ("3xBPFO" in heights and "2xBPFI" in heights
              and heights["3xBPFO"] != heights["2xBPFI"])
        print(("ok   " if ok else "FAIL ") + f"3xBPFO and 2xBPFI labels in different rows: "
              f"{heights.get('3xBPFO')} {heights.get('2xBPFI')}")
        failed |= not ok
        ok = (top is not None and len(heights) >= 12
              and all(h > float(top.group(1)) for h in heights.values()))
        print(("ok   " if ok else "FAIL ") + f"{len(heights)} labels above the graph (its top at "
              f"{top.group(1) if top else None}): lowest {min(heights.values(), default=None)}")
        failed |= not ok
    return 1 if failed else 0


def kept_script(a, work, args):
    """Runs `ohmdem-post plot ARGS` through a gnuplot that keeps its script; the script."""
    wrapper = os.path.join(work, "gnuplot")
    if not os.path.exists(wrapper):
        with open(wrapper, "w") as f:
            f.write(f"#!/bin/sh\ncp \"$1\" {work}/kept.gp\nexec {shutil.which('gnuplot')} \"$@\"\n")
        os.chmod(wrapper, 0o755)
    r = subprocess.run([a.post, "plot"] + args, env=dict(os.environ, OHMDEM_GNUPLOT=wrapper),
                       capture_output=True, text=True)
    return open(os.path.join(work, "kept.gp")).read() if r.returncode == 0 else r.stderr


def plot_floor(a, work):
    if not shutil.which("gnuplot"):
        print("SKIPPED: gnuplot not installed (Debian package gnuplot-nox)")
        return 77
    failed = False
    # as the healthy demo run: 1.3838 ohm varying by 4e-7 ohm, with its defect lines
    healthy = [1.3838 + 4e-7 * math.sin(2 * math.pi * 31.5 * i / 20000)
               + 1e-7 * math.sin(2 * math.pi * 624.8 * i / 20000) for i in range(4000)]
    sig = run_folder(work, "healthy", healthy)
    script = kept_script(a, work, ["--kind", "signal", "--output", f"{work}/r.png", sig])
    fmt = re.search(r"^set format y '%\.(\d+)g'$", script, re.M)
    # ticks a tenth of the 5e-7 ohm span apart, printed with that format, are all different
    ticks = [1.3838 - 2.5e-7 + k * 5e-8 for k in range(11)]
    ok = fmt is not None and len({"%.*g" % (int(fmt.group(1)), t) for t in ticks}) == 11
    print(("ok   " if ok else "FAIL ") + f"the healthy R's ticks told apart: format "
          f"{fmt.group(0) if fmt else None}")
    failed |= not ok
    for kind in ("spectrum", "envelope"):
        script = kept_script(a, work, ["--kind", kind, "--output", f"{work}/s.png", sig])
        yr = re.search(r"^set yrange \[([0-9.e+-]+):([0-9.e+-]+)\]$", script, re.M)
        ok = (yr is not None and float(yr.group(1)) == 0
              and abs(float(yr.group(2)) / (1e-5 * 1.3838) - 1) < 1e-3
              and "numerical floor" in script)
        print(("ok   " if ok else "FAIL ") + f"the healthy {kind} drawn up to 1e-5 of the mean, "
              f"said so: {yr.group(0) if yr else script[-300:]}")
        failed |= not ok
    defect = [1.3838 * (1 + 0.08 * (math.sin(2 * math.pi * 624.8 * i / 20000) > 0.95))
              for i in range(4000)]
    script = kept_script(a, work, ["--kind", "envelope", "--output", f"{work}/d.png",
                                   run_folder(work, "defect", defect, "inner")])
    ok = "set yrange" not in script and "numerical floor" not in script and "plot " in script
    print(("ok   " if ok else "FAIL ") + "a defect's envelope is autoscaled")
    failed |= not ok
    return 1 if failed else 0


def help_examples(a, work):
    failed = False
    names = set()
    for command in ("stats", "spectrum", "envelope", "frequencies", "diagnose", "plot", "orders",
                    "collect", "acquire"):
        r = subprocess.run([a.post, command, "--help"], capture_output=True, text=True)
        text = " ".join(r.stdout.split())
        # the examples of --bearing and --other-bearing: the words with a digit after "e.g."
        for m in re.finditer(r"--(?:other-)?bearing NAME [^-]*?e\.g\. ([^)]*)\)", text):
            names |= set(re.findall(r"\b([A-Za-z]*[0-9][A-Za-z0-9_-]*)", m.group(1)))
    for name in sorted(names):
        r = subprocess.run([a.post, "frequencies", "--bearing", name, "--omega", "500"],
                           capture_output=True, text=True)
        ok = r.returncode == 0
        print(("ok   " if ok else "FAIL ") + f"--help's example bearing {name}: "
              f"{'accepted' if ok else r.stderr.strip()}")
        failed |= not ok
    if not names:
        print("FAIL no example bearing found in the commands' --help")
        failed = True
    return 1 if failed else 0


def suggested(message):
    """The acquire command a baseline-rate error suggests, and what it says to rerun with."""
    m = re.search(r": (ohmdem-post acquire .*?), then diagnose (.*)$", message.strip())
    return (shlex.split(m.group(1)), m.group(2)) if m else (None, message.strip())


def baseline_rate(a, work):
    import random
    rng = random.Random(2)
    failed = False
    a.post = os.path.abspath(a.post)
    os.chdir(work)
    with open("base48.txt", "w") as f:
        f.write("".join(f"{rng.gauss(0, 1)!r}\n" for _ in range(48000)))
    with open("rec12.txt", "w") as f:
        f.write("".join(f"{rng.gauss(0, 1)!r}\n" for _ in range(12000)))
    with open("rec12_stamped.txt", "w") as f:
        f.write("# time a\n" + "".join(f"{i / 12000!r} {rng.gauss(0, 1)!r}\n"
                                       for i in range(12000)))
    bearing = ["--bearing", "6205", "--rpm", "1797"]
    cases = [  # (the record's command, how the rerun is made from what the message says)
        ("baseline faster, text", ["rec12.txt", "--rate", "12000"] + bearing
         + ["--baseline", "base48.txt", "--baseline-rate", "48000"]),
        ("baseline faster, the record time-stamped", ["rec12_stamped.txt"] + bearing
         + ["--baseline", "base48.txt", "--baseline-rate", "48000"]),
        ("record faster", ["base48.txt", "--rate", "48000"] + bearing
         + ["--baseline", "rec12.txt", "--baseline-rate", "12000"]),
    ]
    for what, args in cases:
        r = subprocess.run([a.post, "diagnose"] + args, capture_output=True, text=True)
        cmd, then = suggested(r.stderr)
        if r.returncode == 0 or cmd is None:
            print(f"FAIL {what}: no acquire command in the error: {r.stderr.strip()}")
            failed = True
            continue
        q = subprocess.run([a.post] + cmd[1:], capture_output=True, text=True)
        ok = q.returncode == 0
        print(("ok   " if ok else "FAIL ") + f"{what}: {' '.join(cmd)}: "
              f"{'ran' if ok else q.stderr.strip()}")
        failed |= not ok
        if not ok:
            continue
        new = cmd[cmd.index("--output") + 1]
        rerun = list(args)
        if then.startswith("with --baseline"):  # the baseline replaced, its rate dropped
            words = shlex.split(then.split(" (")[0])[1:]
            i = rerun.index("--baseline-rate")
            del rerun[i:i + 2]
            rerun[rerun.index("--baseline") + 1] = new
            rerun += words[2:]
        else:  # the record replaced, without --rate
            rerun[0] = new
            if "--rate" in rerun:
                i = rerun.index("--rate")
                del rerun[i:i + 2]
        q = subprocess.run([a.post, "diagnose"] + rerun, capture_output=True, text=True)
        ok = q.returncode == 0 and re.search(r"^defect: ", q.stdout, re.M) is not None
        print(("ok   " if ok else "FAIL ") + f"{what}: diagnose {' '.join(rerun)}: "
              f"{'diagnosed' if ok else q.stderr.strip()}")
        failed |= not ok
    return 1 if failed else 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("test")
    ap.add_argument("--post", required=True)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="newcomer_") as work:
        tests = {"plot_script": plot_script, "plot_floor": plot_floor,
                 "diagnose_floor": diagnose_floor, "help_examples": help_examples,
                 "baseline_rate": baseline_rate}
        return tests[a.test](a, work)


if __name__ == "__main__":
    sys.exit(main())

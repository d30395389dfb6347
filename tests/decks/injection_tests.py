#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""No user string reaches a shell (issue: nothing runs that was not asked for). Every form of
shell injection (; $(...) backticks | newline quotes) is put into each place a user gives a
string, and the command it hides (touch MARKER) must never run: the marker file is never
created. The runs themselves may finish or stop with an error; they never run the command.

  deck     -var out, -var restart_file and -var tslide of inputs/bearing_6208/in.bearing
  sweep    a case-table cell and a -var for all cases of in.sweep (partitions)
  slurm    a case-table cell, ROOT, TEND and K of inputs/cluster/sweep_slurm.sh (one task by hand)
  study    the study drivers: no shell=True / os.system / os.popen in studies/ and
           inputs/cluster/, and studies/common.py's run() with the forms in its values
  static   no `shell` line with a variable in the decks (the commands use deck_files)
  run_json a lubricant path holding a double quote, and one in a folder named
           x","omega_inner":5000,"y":" : run.json stays valid JSON, the path one string value,
           omega_inner once and the run's own (deck_files json writes every string)

Usage: injection_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import argparse
import csv
import glob
import os
import re
import subprocess
import sys
import tempfile

from deck_checks import check, finish

# Each form hides `touch MARK` (MARK: a file name in the working folder).
FORMS = {
    "semicolon": "x;touch {m}",
    "dollar": "x$(touch {m})",
    "backtick": "x`touch {m}`",
    "pipe": "x|touch {m}",
    "newline": "x\ntouch {m}",
    "single_quote": "x';touch {m};'",
    "double_quote": 'x";touch {m};"',
    "and": "x&&touch {m}",
    # no blank (LIGGGHTS splits a line at blanks, which stops the forms above early)
    "semicolon_ifs": "x;touch${{IFS}}{m}",
    "dollar_ifs": "x$(touch${{IFS}}{m})",
}


def markers(work):
    # files only: stock `shell mkdir` splits a value at blanks into folders of such names
    return sorted(os.path.basename(p) for p in glob.glob(os.path.join(work, "MARK_*"))
                  if os.path.isfile(p))


def run(cmd, work, env=None, timeout=120):
    r = subprocess.run(cmd, cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, errors="replace", timeout=timeout)
    # finished or stopped with an error: never killed by a signal (an abort, a crash)
    check(r.returncode >= 0 and r.returncode != 134, f"{cmd[:3]}...: exit {r.returncode}")
    return r


def deck(a, work, **var):
    cmd = [a.exe, "-in", os.path.join(a.src, "inputs", "bearing_6208", "in.bearing"),
           "-screen", "none", "-log", "none", "-var", "tend", "2e-6", "-var", "dt", "1e-6"]
    for k, v in var.items():
        cmd += ["-var", k, v]
    return cmd


def test_deck(a, work):
    for name, form in FORMS.items():
        for var in ("out", "restart_file", "tslide"):
            mark = f"MARK_{var}_{name}"
            value = form.format(m=mark)
            extra = {"out": value} if var == "out" else {"out": "o_" + var + "_" + name, var: value}
            if var == "restart_file":
                extra["start"] = "restart"
            # the same through the resume check of sweeps (sweep_case.sh gets out)
            for resume in ("0", "1"):
                run(deck(a, work, resume=resume, **extra), work)
            check(not os.path.isfile(os.path.join(work, mark)), f"deck -var {var} {value!r}: "
                  f"the hidden command ran")
    # a plain run still works, into a new nested folder
    r = run(deck(a, work, out="a/b/c"), work)
    check(r.returncode == 0 and os.path.isfile(os.path.join(work, "a/b/c/signal.txt")),
          f"deck: a plain run into a/b/c: exit {r.returncode}\n{r.stdout[-600:]}")


def sweep_table(work, name, cells):
    path = os.path.join(work, f"cases_{name}.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")  # a cell with a newline or a quote: quoted
        w.writerow(["tslide", "size"])
        for c in cells:
            w.writerow([c, "1"])
    return path


def test_sweep(a, work):
    here = os.path.join(a.src, "inputs", "bearing_6208")
    for name, form in FORMS.items():
        if "\n" in form or '"' in form:
            continue  # the table refuses them (control character, double quote): said below
        mark = f"MARK_sweep_{name}"
        table = sweep_table(work, name, [form.format(m=mark)])
        r = run([a.exe, "-in", os.path.join(here, "in.sweep"), "-var", "here", here,
                 "-var", "bearing_deck", os.path.join(here, "in.bearing"), "-var", "cases", table,
                 "-var", "root", f"sw_{name}", "-var", "tend", "2e-6", "-var", "dt", "1e-6",
                 "-var", "defect", "none", "-screen", "none", "-log", f"sw_{name}.log"], work)
        check(not os.path.isfile(os.path.join(work, mark)),
              f"sweep: case-table cell {form!r}: the hidden command ran")
        mark2 = f"MARK_sweepvar_{name}"
        run([a.exe, "-in", os.path.join(here, "in.sweep"), "-var", "here", here,
             "-var", "bearing_deck", os.path.join(here, "in.bearing"), "-var", "sizes", "1",
             "-var", "root", f"sv_{name}", "-var", "tend", "2e-6", "-var", "dt", "1e-6",
             "-var", "tslide", form.format(m=mark2), "-screen", "none", "-log",
             f"sv_{name}.log"], work)
        check(not os.path.isfile(os.path.join(work, mark2)),
              f"sweep: -var tslide {form!r} for all cases: the hidden command ran")
    for name in ("newline", "double_quote"):
        table = sweep_table(work, name, [FORMS[name].format(m="MARK_table")])
        r = subprocess.run(["/usr/bin/python3", os.path.join(a.src, "inputs", "cluster",
                                                             "cases.py"), "check", table],
                           capture_output=True, text=True)
        check(r.returncode == 2 and "double quote or a control character" in r.stderr,
              f"sweep: a cell with {name} refused by the table check ({r.stderr.strip()})")


def test_slurm(a, work):
    script = os.path.join(a.src, "inputs", "cluster", "sweep_slurm.sh")
    base = dict(os.environ, OHMDEM=a.exe, SLURM_ARRAY_TASK_ID="0")
    base.pop("SLURM_JOB_ID", None)
    for name, form in FORMS.items():
        cell = form.format(m=f"MARK_slurm_cell_{name}")
        table = sweep_table(work, "slurm_" + name, ["0.015" if "\n" in form or '"' in form
                                                    else cell])
        env = dict(base, ROOT=f"sl_{name}/" + form.format(m=f"MARK_slurm_root_{name}"),
                   TEND="2e-6" + form.format(m=f"MARK_slurm_tend_{name}"))
        run(["bash", script, table, "1"], work, env=env)
        run(["bash", script, table, "1"], work, env=dict(base, ROOT=f"sl_{name}", TEND="2e-6"))
        run(["bash", script, table, form.format(m=f"MARK_slurm_k_{name}")], work,
            env=dict(base, ROOT=f"sk_{name}"))
    run(["bash", script, sweep_table(work, "slurm_k", ["0.015"]), "a[$(touch MARK_slurm_arith)]"],
        work, env=dict(base, ROOT="sk_arith"))
    made = markers(work)
    check(not made, f"slurm: the hidden commands ran: {made}")


def test_study(a, work):
    for path in glob.glob(os.path.join(a.src, "studies", "*.py")) + glob.glob(
            os.path.join(a.src, "inputs", "cluster", "*.py")):
        text = open(path).read()
        for bad in ("shell=True", "os.system(", "os.popen(", "commands.getoutput"):
            check(bad not in text, f"study: {os.path.relpath(path, a.src)} uses {bad}")
    sys.path.insert(0, os.path.join(a.src, "studies"))
    os.environ["OHMDEM"] = a.exe
    import common  # noqa: E402  (the drivers' shared module, with OHMDEM set)
    for name, form in FORMS.items():
        cmd = common.deck_command(common.BEARING_DECK, common.variables(
            {"out": form.format(m=f"MARK_study_out_{name}"), "tend": 2e-6, "dt": 1e-6,
             "tslide": form.format(m=f"MARK_study_ts_{name}")}) + ["-screen", "none"])
        subprocess.run(cmd, cwd=work, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    made = markers(work)
    check(not made, f"study: the hidden commands ran: {made}")


def test_static(a, work):
    for path in glob.glob(os.path.join(a.src, "inputs", "*", "in.*")) + [
            os.path.join(a.src, "inputs", "cluster", "cases.py")]:
        for i, line in enumerate(open(path), 1):
            if re.match(r'\s*("?)shell\b', line) or re.search(r'"shell ', line) or \
                    re.search(r'f"shell ', line):
                check(False, f"static: {os.path.relpath(path, a.src)}:{i}: a shell line: "
                      f"{line.strip()}")


def test_run_json(a, work):
    import json
    import shutil
    vg68 = os.path.join(a.src, "inputs", "lubricants", "VG68")
    for name, folder in (("quote", 'q"d'), ("key", 'x","omega_inner":5000,"y":"'),
                         ("backslash", "b\\s")):
        os.makedirs(os.path.join(work, folder), exist_ok=True)
        shutil.copy(vg68, os.path.join(work, folder, "oil"))
        path = "./" + folder + "/oil"
        out = "json_" + name
        r = run(deck(a, work, out=out, lubricant=path), work)
        try:
            with open(os.path.join(work, out, "run.json")) as f:
                pairs = json.load(f, object_pairs_hook=lambda p: p)
        except (OSError, ValueError) as e:
            pairs = []
            print(f"note: run_json {name}: {e}")
        omegas = [v for k, v in pairs if k == "omega_inner"]
        keys = [k for k, _ in pairs]
        check(r.returncode == 0 and omegas == [500] and len(keys) == len(set(keys)) and
              dict(pairs).get("lubricant") == path,
              f"run_json: lubricant {path!r}: exit {r.returncode}, valid run.json, omega_inner "
              f"{omegas}, the path one value ({dict(pairs).get('lubricant')!r})")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test", choices=["deck", "sweep", "slurm", "study", "static", "run_json"])
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    a = p.parse_args()
    with tempfile.TemporaryDirectory(prefix=f"inject_{a.test}_") as work:
        globals()[f"test_{a.test}"](a, work)
        made = markers(work)
        check(not made, f"{a.test}: marker files created: {made}")
    finish()


if __name__ == "__main__":
    main()

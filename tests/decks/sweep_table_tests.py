#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Case tables (doc/case_table.md) through every launcher: a 2 x 3 grid (F x defect size) through
LIGGGHTS' partitions (inputs/bearing_6208/in.sweep) and through the Slurm array script run by
hand (inputs/cluster/sweep_slurm.sh, every task index), collected by `ohmdem-post collect ROOT`
with each row's parameters checked against its CSV row; resume; the deck variables of one case
not leaking into the next; bad tables.
cells: a cell without its deck variable's form (a size "2;touch x", a text size) is refused by
`cases.py check` naming line, column, variable and form; in a partition sweep that case alone
fails, named, the valid rows run and the summary names it. progress: a Slurm task run again
keeps one line per case in finished.txt, its counter never passes the table. engine_error: a
value the engine refuses (F -5) on 2 partitions stops that partition alone: the other rows
run, the terminal says which partition stopped and why, the summary names the case.
Usage: sweep_table_tests.py partitions|slurm|reset|errors|cells|progress --exe OHMDEM --post POST
       --src DIR"""
import argparse
import csv
import io
import os
import re
import subprocess
import tempfile

from deck_checks import check, finish

TEND = "0.001"  # a few hundred steps: the launchers are under test, not the physics
GRID = ["F=200,400", "size=0.5,1,2"]


def run(cmd, cwd, env=None):
    res = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, errors="replace",
                         env=dict(os.environ, **(env or {})))
    return res.returncode, res.stdout + res.stderr


class Ctx:
    def __init__(self, a, wd):
        self.exe = os.path.abspath(a.exe)
        self.post = os.path.abspath(a.post)
        self.src = os.path.abspath(a.src)
        self.deck = os.path.join(self.src, "inputs", "bearing_6208")
        self.cases_py = os.path.join(self.src, "inputs", "cluster", "cases.py")
        self.slurm = os.path.join(self.src, "inputs", "cluster", "sweep_slurm.sh")
        self.wd = wd

    def grid(self, name, *specs):
        path = os.path.join(self.wd, name)
        rc, out = run(["/usr/bin/python3", self.cases_py, "grid", *specs, "--output", path],
                      self.wd)
        check(rc == 0, f"cases.py grid {' '.join(specs)} {out.strip()}")
        return path

    def sweep(self, root, table, np=2, *extra):
        mpi = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np)] if np > 1 else []
        part = ["-partition", f"{np}x1"] if np > 1 else []
        return run(mpi + [self.exe, *part, "-in", os.path.join(self.deck, "in.sweep"),
                          "-var", "here", self.deck,
                          "-var", "bearing_deck", os.path.join(self.deck, "in.bearing"),
                          "-var", "root", root, "-var", "tend", TEND, "-var", "cases", table,
                          *extra], self.wd)

    def slurm_task(self, table, k, task, root):
        env = {"OHMDEM": self.exe, "ROOT": root, "TEND": TEND}
        if task is not None:
            env["SLURM_ARRAY_TASK_ID"] = str(task)
        return run(["bash", self.slurm, table, str(k)], self.wd, env)

    def collect(self, root):
        """`ohmdem-post collect ROOT` (no --recursive): {folder name: row}."""
        rc, out = run([self.post, "collect", "--format", "csv", "--from", "0", root], self.wd)
        lines = [l for l in out.splitlines() if l and not l.startswith(("#", "WARNING"))]
        if rc != 0 or not lines:
            check(False, f"ohmdem-post collect {root}: {out[-500:]}")
            return {}
        rows = list(csv.DictReader(io.StringIO("\n".join(lines))))
        return {os.path.basename(r["run"]): r for r in rows}


def table_rows(path):
    return list(csv.DictReader(l for l in open(path) if not l.startswith("#")))


def check_collected(ctx, root, table, what):
    """Every row of the table collected once, in its own folder, with its F and size."""
    rows = ctx.collect(root)
    want = table_rows(table)
    check(len(rows) == len(want) == 6, f"{what}: collect ROOT gives the 6 cases ({len(rows)})")
    for r in want:
        folder = f"F_{r['F']}_size_{r['size']}"
        got = rows.get(folder)
        check(got is not None and float(got["F"]) == float(r["F"]) and
              float(got["size_deg"]) == float(r["size"]) and got["defect"] == "inner" and
              float(got["tend"]) == float(TEND) and got["status"] == "finished",
              f"{what}: case {folder}: run.json F, size_deg as in its CSV row "
              f"(F {got and got.get('F')}, size_deg {got and got.get('size_deg')})")


def mtimes(root):
    return {f: os.stat(os.path.join(root, f, "signal.txt")).st_mtime_ns
            for f in os.listdir(root) if os.path.exists(os.path.join(root, f, "signal.txt"))}


def test_partitions(ctx):
    table = ctx.grid("cases.csv", *GRID)
    want = [["F", "size"], ["200", "0.5"], ["200", "1"], ["200", "2"],
            ["400", "0.5"], ["400", "1"], ["400", "2"]]
    check(list(csv.reader(open(table))) == want, "grid: the 6 rows, the first variable slowest")
    root = os.path.join(ctx.wd, "sweep")
    rc, out = ctx.sweep(root, table)
    check(rc == 0 and "sweep: 6/6 cases done" in out, "2 partitions: the 6 cases done")
    check_collected(ctx, root, table, "partitions")
    # Resume: the same command skips every case, files untouched; a case without its done
    # mark (a kill) runs again.
    before = mtimes(root)
    os.remove(os.path.join(root, "F_400_size_1", "run.done.json"))
    rc, out = ctx.sweep(root, table)
    after = mtimes(root)
    check(rc == 0 and out.count("already finished with the same parameters: skipped") == 5,
          "resume: the 5 finished cases said skipped")
    check(all(after[f] == before[f] for f in before if f != "F_400_size_1") and
          after["F_400_size_1"] != before["F_400_size_1"],
          "resume: finished cases untouched, the unfinished one run again")
    check_collected(ctx, root, table, "partitions after resume")


def test_slurm(ctx):
    table = ctx.grid("cases.csv", *GRID)
    root = os.path.join(ctx.wd, "slurm")
    k = 2
    rc, out = run(["bash", ctx.slurm, "--tasks", table, str(k)], ctx.wd)
    check(rc == 0 and out.strip() == "3", f"--tasks: 6 cases, 2 per task: 3 tasks ({out.strip()})")
    # --submit hands sbatch the array size from the table (a stand-in sbatch records its call).
    fake = os.path.join(ctx.wd, "bin")
    os.makedirs(fake)
    with open(os.path.join(fake, "sbatch"), "w") as fh:
        fh.write(f'#!/bin/sh\necho "$@" > {ctx.wd}/sbatch_args\n')
    os.chmod(os.path.join(fake, "sbatch"), 0o755)
    rc, out = run(["bash", ctx.slurm, "--submit", table, str(k)], ctx.wd,
                  {"PATH": fake + os.pathsep + os.environ["PATH"], "ROOT": root})
    args = open(os.path.join(ctx.wd, "sbatch_args")).read().split() if rc == 0 else []
    check(args == ["--array=0-2", ctx.slurm, table, "2"],
          f"--submit: sbatch --array=0-2 SCRIPT TABLE 2 ({' '.join(args)} {out[-200:]})")
    for task in range(3):
        rc, out = ctx.slurm_task(table, k, task, root)
        check(rc == 0, f"array task {task} by hand (SLURM_ARRAY_TASK_ID={task}) {out[-300:]}")
    check_collected(ctx, root, table, "slurm")
    before = mtimes(root)
    rc, out = ctx.slurm_task(table, k, 1, root)
    check(rc == 0 and out.count("already finished with the same parameters: skipped") == 2 and
          mtimes(root) == before, "resume: task 1 again skips its 2 finished cases")


def test_reset(ctx):
    """One partition, two cases in turn: the second (machado2014, the deck's default bearing) must
    not keep what the first (the 6205) set - its balls, and F, whose default scales with them."""
    table = os.path.join(ctx.wd, "bearings.csv")
    open(table, "w").write("# two bearings in turn\nbearing\n6205\nmachado2014\n")
    root = os.path.join(ctx.wd, "bearings")
    rc, out = ctx.sweep(root, table, 1)
    rows = ctx.collect(root)
    b5, b8 = rows.get("bearing_6205", {}), rows.get("bearing_machado2014", {})
    # machado2014 (the paper's bearing): 13 balls, F default 320 N; the 6205: 9 balls.
    check(rc == 0 and b5.get("nb") == "9" and b8.get("nb") == "13",
          f"bearing column: 9 then 13 balls ({b5.get('nb')}, {b8.get('nb')})")
    check(b8.get("F") and float(b8["F"]) == 320.0 and float(b5["F"]) != 320.0,
          f"the second case's F default is machado2014's 320 N, not the 6205's "
          f"({b5.get('F')}, {b8.get('F')})")


def test_errors(ctx):
    def table(name, text):
        path = os.path.join(ctx.wd, name)
        open(path, "w").write(text)
        return path

    def bad(cmd, expect, what, env=None):
        rc, out = run(cmd, ctx.wd, env)
        check(rc != 0 and all(e in out for e in expect),
              f"{what}: non-zero exit and {expect} in the message (rc {rc}: {out.strip()[-300:]})")

    py = ["/usr/bin/python3", ctx.cases_py]
    deck = ["--deck", os.path.join(ctx.deck, "in.bearing"),
            "--catalog", os.path.join(ctx.src, "inputs", "bearings")]
    cases = [("no_header.csv", "200,0.5\n400,1\n", ["no_header.csv:1: column 1 header '200'",
                                                    "header line missing"]),
             ("bad_name.csv", "F,si ze\n200,0.5\n", ["bad_name.csv:1: column 2 header 'si ze'",
                                                    "not a deck variable name"]),
             ("ragged.csv", "F,size\n200,0.5\n400\n", ["ragged.csv:3: 1 cells, the header has 2"]),
             ("empty.csv", "", ["empty.csv is empty"]),
             ("header_only.csv", "F,size\n\n", ["header_only.csv has a header", "no case"]),
             ("empty_cell.csv", "F,size\n200,\n", ["empty_cell.csv:2: column 2 (size) is empty"]),
             ("twice.csv", "F,size\n200,1\n# c\n200,1\n",
              ["twice.csv:4: the case repeats line 2"]),
             ("reserved.csv", "out,size\na,1\n", ["reserved.csv:1: column 1 header 'out'"]),
             ("typo.csv", "F,sise\n200,1\n", ["typo.csv: column 2 (sise) is not a variable of "
                                              "the deck"])]
    for name, text, expect in cases:
        bad(py + ["check", table(name, text)] + deck, expect, f"cases.py check {name}")
    bad(py + ["check", os.path.join(ctx.wd, "nothere.csv")], ["nothere.csv: cannot be read"],
        "a missing table")
    bad(py + ["grid", "F=100,,200"], ["F=100,,200", "empty value"], "grid: an empty value")
    bad(py + ["grid", "2F=1"], ["'2F' is not a deck variable name"], "grid: a bad name")

    # The launchers stop on a bad table with the same message.
    rc, out = ctx.sweep(os.path.join(ctx.wd, "bad_sweep"), os.path.join(ctx.wd, "ragged.csv"), 1)
    check(rc != 0 and "ragged.csv:3: 1 cells, the header has 2" in out,
          f"in.sweep with a ragged table: non-zero exit and the file:line (rc {rc})")
    rc, out = ctx.sweep(os.path.join(ctx.wd, "bad_sizes"), "none", 1, "-var", "sizes", "1 2",
                        "-var", "ncases", "3")
    check(rc != 0 and "-var ncases 3 but -var sizes has 2 values" in out,
          "in.sweep: -var ncases disagreeing with -var sizes is an error")
    good = ctx.grid("good.csv", *GRID)
    root = os.path.join(ctx.wd, "bad_slurm")
    bad(["bash", ctx.slurm, table("ragged2.csv", "F,size\n1,2,3\n"), "2"],
        ["ragged2.csv:2: 3 cells"], "sweep_slurm.sh: a ragged table",
        {"SLURM_ARRAY_TASK_ID": "0", "ROOT": root})
    bad(["bash", ctx.slurm, good, "0"], ["K (cases per task) must be a whole number >= 1, got '0'"],
        "sweep_slurm.sh: K = 0", {"SLURM_ARRAY_TASK_ID": "0", "ROOT": root})
    bad(["bash", ctx.slurm, good, "two"], ["K (cases per task)", "got 'two'"],
        "sweep_slurm.sh: K not a number", {"SLURM_ARRAY_TASK_ID": "0", "ROOT": root})
    bad(["bash", ctx.slurm, good, "4"],
        ["SLURM_ARRAY_TASK_ID=2 out of range", "has 6 cases, 4 per task: tasks 0..1"],
        "sweep_slurm.sh: task index out of range", {"SLURM_ARRAY_TASK_ID": "2", "ROOT": root})
    bad(["bash", ctx.slurm, good, "4"], ["SLURM_ARRAY_TASK_ID is not set"],
        "sweep_slurm.sh: no task index", {"ROOT": root})
    check(not os.path.exists(os.path.join(root, "sweep_cases.csv")),
          "sweep_slurm.sh: nothing run on a bad call")


def write_table(ctx, name, text):
    path = os.path.join(ctx.wd, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def test_cells(ctx):
    table = write_table(ctx, "cells.csv", "F,size\n200,0.5\n200,2;touch MARK_cells\n"
                                          "200,large\n400,1\n")
    rc, out = run(["/usr/bin/python3", ctx.cases_py, "check", table,
                   "--deck", os.path.join(ctx.deck, "in.bearing")], ctx.wd)
    want = [f"{table}:3: column 2 (size): deck variable size: expected a number, got "
            "'2;touch MARK_cells'",
            f"{table}:4: column 2 (size): deck variable size: expected a number, got 'large'",
            "(2 of 4 cases; the others are valid)"]
    check(rc == 2 and all(w in out for w in want),
          f"cells: cases.py check refuses the cells by line, column and form (exit {rc}): "
          f"{out.strip()[:300]}")
    root = os.path.join(ctx.wd, "cells")
    rc, out = ctx.sweep(root, table, 1)
    folders = {f: os.path.exists(os.path.join(root, f, "signal.txt"))
               for f in ("F_200_size_0.5", "F_400_size_1")}
    check(all(folders.values()), f"cells: the valid rows ran ({folders}, exit {rc})")
    check("sweep: case F=200,size=large FAILED: " in out and
          "deck variable size: expected a number, got 'large'" in out,
          "cells: the bad case failed alone, named with its variable and form")
    check("sweep: summary: 2 of 4 cases done, 2 FAILED (F=200,size=2;touch MARK_cells; "
          "F=200,size=large), 0 not finished" in out,
          f"cells: the summary names the failed cases: "
          f"{[l for l in out.splitlines() if 'summary' in l]}")
    check(not os.path.exists(os.path.join(ctx.wd, "MARK_cells")), "cells: nothing ran")


def test_progress(ctx):
    table = ctx.grid("progress.csv", "size=0.5,1")
    root = os.path.join(ctx.wd, "progress")
    outs = [ctx.slurm_task(table, 2, 0, root) for _ in range(2)]
    counts = [l for _, out in outs for l in out.splitlines()
              if re.match(r"sweep: \d+/\d+ cases done", l)]
    lines = open(os.path.join(root, "finished.txt")).read().splitlines()
    check(all(rc == 0 for rc, _ in outs) and sorted(lines) == ["size=0.5 done", "size=1 done"],
          f"progress: task 0 run twice: finished.txt holds each case once: {lines}")
    check(counts and all(int(l.split()[1].split("/")[0]) <= 2 for l in counts) and
          counts[-1].startswith("sweep: 2/2 cases done"),
          f"progress: the counter never passes the table: {counts}")


def test_engine_error(ctx):
    table = write_table(ctx, "engine.csv", "F,size\n200,1\n-5,1\n300,1\n400,1\n")
    root = os.path.join(ctx.wd, "engine")
    rc, out = ctx.sweep(root, table, 2)
    ran = [f for f in ("F_200_size_1", "F_300_size_1", "F_400_size_1")
           if os.path.exists(os.path.join(root, f, "signal.txt"))]
    check(rc != 0 and len(ran) == 3, f"engine_error: the valid rows ran on the other partition "
          f"({ran}), the sweep exits non-zero ({rc})")
    check(re.search(r"ERROR on partition \d: fix bearing/race: keyword 'force' expects the load "
                    r"magnitude F > 0 \(N\), or v_NAME, got '-5' \(its processes stop; the "
                    r"other partitions go on\)", out) is not None,
          "engine_error: the terminal says which partition stopped and why")
    check("sweep: summary: 3 of 4 cases done, 0 FAILED, 1 not finished (started, not ended: "
          "F=-5,size=1)" in out,
          f"engine_error: the summary names the case: "
          f"{[l for l in out.splitlines() if 'summary' in l]}")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test", choices=["partitions", "slurm", "reset", "errors", "cells",
                                    "progress", "engine_error"])
    p.add_argument("--exe", required=True)
    p.add_argument("--post", required=True)
    p.add_argument("--src", required=True)
    a = p.parse_args()
    with tempfile.TemporaryDirectory(prefix="ohmdem_cases_") as wd:
        ctx = Ctx(a, wd)
        {"partitions": test_partitions, "slurm": test_slurm, "reset": test_reset,
         "errors": test_errors, "cells": test_cells, "progress": test_progress,
         "engine_error": test_engine_error}[a.test](ctx)
    finish()


if __name__ == "__main__":
    main()

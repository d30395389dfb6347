#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Scores `ohmdem-post diagnose` on folders of measured records with their truth.

    diagnose_benchmark.py --exe build/ohmdem-post --root DIR [--cwru-labels LABELS.csv]
                          [TRUTH.csv ...]

TRUTH.csv: a header `file,truth,args`, then one row per record: the file (relative to --root),
its truth (none for a healthy bearing, inner, outer, ball, cage, or fault when only the presence
of a fault is known) and the diagnose options for it (rate, speed, bearing, variable), separated
by spaces. Each table is one rig (its name: the file's stem).
--cwru-labels: the labelled CWRU folder's labels.csv (record, faulty_bearing, fault, ...,
faulty_channel): each record gives two rows, the faulty channel with its label and the other
channel (a bearing with no seeded fault) as healthy; rig `cwru-labelled`.

Prints each verdict, per rig and over all the confusion matrix (truth x verdict) and the
healthy channels' false alarms: healthy records named after a family (inner, outer, ball,
cage; cage?ball is a cage verdict with a possible ball defect). Healthy records merely flagged
(unidentified: a detection test fired; ambiguous) are counted apart, and so are those whose
impulses are the other bearing's (other-bearing). A ball record is hedged when the verdict is
not ball but names a possible ball defect (cage?ball, or a ball candidate).
Exit status 0; --require-no-false-alarm, --require-races-right, --min-races-right N,
--min-ball-right-or-hedged N and --max-healthy-flagged N turn the goals into an exit status
(1 when missed).
"""
import argparse
import csv
import json
import os
import shlex
import subprocess
import sys

VERDICTS = ["none", "inner", "outer", "ball", "cage", "cage?ball", "ambiguous", "unidentified",
            "other-bearing"]
FAMILIES = {"inner", "outer", "ball", "cage", "cage?ball"}
CWRU = {"drive end": ("DE_time", "6205-2RS_JEM", "FE_time", "6203-2RS_JEM"),
        "fan end": ("FE_time", "6203-2RS_JEM", "DE_time", "6205-2RS_JEM")}


def diagnose(exe, path, args):
    out = subprocess.run([exe, "diagnose", path, *shlex.split(args), "--no-size", "--format",
                          "json"], capture_output=True, text=True)
    if out.returncode != 0:
        return "error", 0.0, "", out.stderr.strip()
    j = json.loads(out.stdout)
    note = j.get("candidate", "") or ""
    if j["defect"] == "other-bearing":  # candidate: the other bearing's family
        return "other-bearing", j["score"], "", "the other bearing's " + j["fundamental"]
    verdict = j["defect"]
    if verdict == "cage" and note == "ball":
        verdict = "cage?ball"  # cage (possible ball defect)
    return verdict, j["score"], note, ("candidate " + note) if note else ""


def cwru_rows(labels):
    """Two rows per labelled CWRU record: its faulty channel and the other (healthy) one."""
    rows = []
    folder = os.path.basename(os.path.dirname(os.path.abspath(labels)))
    with open(labels, newline="") as f:
        for r in csv.DictReader(f):
            side = "drive end" if r["faulty_bearing"].startswith("drive end") else "fan end"
            chan, bearing, other_chan, other_bearing = CWRU[side]
            if chan != r["faulty_channel"]:
                raise SystemExit(f"{labels}: {r['record']}: faulty_channel {r['faulty_channel']}"
                                 f" is not the {side}'s {chan}")
            fault = r["fault"]
            truth = ("inner" if fault.startswith("inner") else
                     "outer" if fault.startswith("outer") else
                     "ball" if fault.startswith("ball") else None)
            if truth is None:
                raise SystemExit(f"{labels}: {r['record']}: unknown fault '{fault}'")
            path = os.path.join(folder, r["record"])
            common = f"--rate {r['rate_hz']} --rpm-variable RPM"
            note = f"{fault}, {r['size_in']} in, {r['load_hp']} hp, {r['rate_hz']} Hz"
            rows.append({"file": path, "truth": truth, "rig": "cwru-labelled", "note": note,
                         "args": f"--variable {chan} {common} --bearing {bearing} "
                                 f"--other-bearing {other_bearing} --other-channel {other_chan}"})
            rows.append({"file": path, "truth": "none", "rig": "cwru-labelled",
                         "note": f"{other_chan}: the healthy bearing of a {side} {fault}",
                         "args": f"--variable {other_chan} {common} --bearing {other_bearing} "
                                 f"--other-bearing {bearing} --other-channel {chan}"})
    return rows


class Score:
    def __init__(self):
        self.matrix = {}
        self.healthy = self.alarms = self.flagged = self.other = 0
        self.races = self.races_right = self.balls = self.balls_right = self.balls_hedged = 0

    def add(self, truth, verdict, candidate):
        self.matrix.setdefault(truth, {}).setdefault(verdict, 0)
        self.matrix[truth][verdict] += 1
        if truth == "none":
            self.healthy += 1
            self.alarms += verdict in FAMILIES
            self.flagged += verdict in ("unidentified", "ambiguous")
            self.other += verdict == "other-bearing"
        if truth in ("inner", "outer"):
            self.races += 1
            self.races_right += verdict == truth
        if truth == "ball":
            self.balls += 1
            self.balls_right += verdict == "ball"
            self.balls_hedged += verdict != "ball" and (verdict == "cage?ball" or
                                                         candidate == "ball")

    def print(self, title):
        cols = VERDICTS + sorted({v for t in self.matrix.values() for v in t} - set(VERDICTS))
        cols = [c for c in cols if any(t.get(c, 0) for t in self.matrix.values())]
        print(f"\n{title}: confusion matrix (rows: truth, columns: verdict)")
        print(f"{'':<8}" + "".join(f"{c:>14}" for c in cols))
        for t in sorted(self.matrix):
            print(f"{t:<8}" + "".join(f"{self.matrix[t].get(c, 0):>14}" for c in cols))
        if self.healthy:
            print(f"false alarms (healthy channels named after a family): {self.alarms} of "
                  f"{self.healthy} ({100.0 * self.alarms / self.healthy:.1f} %); healthy flagged "
                  f"unidentified/ambiguous: {self.flagged} of {self.healthy}; healthy whose "
                  f"impulses are the other bearing's: {self.other} of {self.healthy}")
        if self.races:
            print(f"inner and outer records right: {self.races_right} of {self.races}")
        if self.balls:
            print(f"ball records right: {self.balls_right}, hedged (possible ball): "
                  f"{self.balls_hedged}, of {self.balls}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", required=True, help="the ohmdem-post executable")
    ap.add_argument("--root", default=".", help="folder the truth tables' files are relative to")
    ap.add_argument("--cwru-labels", metavar="LABELS.csv",
                    help="the labelled CWRU records' labels.csv (a folder under --root)")
    ap.add_argument("--require-no-false-alarm", action="store_true")
    ap.add_argument("--require-races-right", action="store_true")
    ap.add_argument("--min-races-right", type=int, default=None, metavar="N",
                    help="fail when fewer than N inner and outer records are right")
    ap.add_argument("--min-ball-right-or-hedged", type=int, default=None, metavar="N",
                    help="fail when fewer than N ball records read ball or possible ball")
    ap.add_argument("--max-healthy-flagged", type=int, default=None, metavar="N",
                    help="fail when more than N healthy records are unidentified or ambiguous")
    ap.add_argument("truth", nargs="*", help="truth tables (CSV: file,truth,args)")
    a = ap.parse_args()
    rows = []
    for table in a.truth:
        rig = os.path.splitext(os.path.basename(table))[0]
        with open(table, newline="") as f:
            for r in csv.DictReader(f):
                rows.append(dict(r, rig=rig, note=""))
    if a.cwru_labels:
        rows += cwru_rows(a.cwru_labels)
    if not rows:
        ap.error("give truth tables or --cwru-labels")
    total, rigs = Score(), {}
    print(f"{'rig':<14} {'file':<44} {'truth':<7} {'verdict':<13} score")
    for r in rows:
        verdict, score, candidate, note = diagnose(a.exe, os.path.join(a.root, r["file"]),
                                                   r["args"])
        truth = r["truth"]
        chan = r["args"].split()[1] if r["args"].startswith("--variable") else ""
        print(f"{r['rig']:<14} {r['file'] + ' ' + chan:<44} {truth:<7} {verdict:<13} "
              f"{score:.2f} {note}{' (' + r['note'] + ')' if r['note'] else ''}")
        total.add(truth, verdict, candidate)
        rigs.setdefault(r["rig"], Score()).add(truth, verdict, candidate)
    for rig, s in rigs.items():
        s.print(rig)
    if len(rigs) > 1:
        total.print("all rigs")
    failed = (a.require_no_false_alarm and total.alarms > 0) or \
             (a.require_races_right and total.races_right < total.races) or \
             (a.min_races_right is not None and total.races_right < a.min_races_right) or \
             (a.min_ball_right_or_hedged is not None and
              total.balls_right + total.balls_hedged < a.min_ball_right_or_hedged) or \
             (a.max_healthy_flagged is not None and total.flagged > a.max_healthy_flagged)
    if failed:
        print("\nFAILED: the benchmark's goals are missed (see the options given)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

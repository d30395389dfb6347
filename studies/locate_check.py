#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""studies/locate_outer.py on held-out places: outer pits under the radial load at
angles and sizes that no bank, study case or margin choice used, on both sides of the load line,
each simulated (0.35 s, as the sizing study's scene), acquired through the study's chain (20 kHz,
16 bits, low noise, acquisition seed 7) and located by locate_outer.py with its defaults (its
margin fixed beforehand). The error of the placed angle, or 'not determined'; a record not placed
is scored on its distance from the load line, either side (locate_outer.py's
distance_from_load_deg), and on whether its interval holds the pit's distance.

  studies/locate_check.py [--cases=ANGLE:SIZE,...] [--rate 2e4 --bank FILE]
                          [--mismatch NAME RECORD_VALUE VALUE] OUT

--rate: another chain's rate (the same 16 bits and low noise), with --bank a template bank for
that chain (studies/template_bank.py --rates R --noise low --kinds outer:radial OUT writes one).
--mismatch: the record's scene with the deck variable NAME at RECORD_VALUE while locate_outer.py
is told VALUE (--var), as when the user knows the scene only roughly (F 336 320: the radial load
5 % above the stated one).

Writes OUT/locate_check.csv and OUT/locate_check.md (one row per case, written as it goes); each
case's runs under OUT/<case>/ (5-7 minutes a case on one core).
"""
import argparse
import json
import os
import subprocess
import sys

import common
import sizing
import template_bank

CASES = [(-48.75, 1.8), (-36.25, 0.9), (-28.75, 0.37), (-21.25, 2.6), (-8.75, 0.6), (8.75, 1.2),
         (13.75, 0.9), (21.25, 0.37), (23.75, 1.8), (36.25, 0.6), (38.75, 2.6), (52.5, 1.2)]
NOISE, SEED = "low", 7
LENGTH = 0.3  # the record's length (s) from sizing.T_FROM, as the sizing study's


def one(out, angle, size, rate, bank, mismatch=None, length=LENGTH):
    """locate_outer.py's answer on the case's record. mismatch (NAME, RECORD_VALUE, VALUE): the
    record's scene has the deck variable at RECORD_VALUE, the runs at VALUE (a scene known to
    the user only roughly). length: the record's (s); other than 0.3 under out/length<L>."""
    extra = {mismatch[0]: mismatch[1]} if mismatch else None
    if length != LENGTH:  # the runs' folders do not name their end
        out = os.path.join(out, f"length{length:g}")
    sim, acq = template_bank.acquired(out, "outer", size, "radial", angle, rate, NOISE, seed=SEED,
                                      tend=sizing.T_FROM + length, allow_fail=False, extra=extra)
    dest = os.path.join(out, f"case_{angle:g}_{size:g}" + ("" if rate == 2e4 else f"_r{rate:g}")
                        + (f"_{mismatch[0]}{mismatch[1]}as{mismatch[2]}" if mismatch else ""))
    r = subprocess.run(["/usr/bin/python3", os.path.join(common.STUDIES, "locate_outer.py"),
                        "--metadata", os.path.join(sim, "run.json"), "--from", repr(sizing.T_FROM)]
                       + (["--bank", bank] if bank else [])
                       + (["--var", mismatch[0], mismatch[2]] if mismatch else []) + [acq, dest],
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"locate_check: locate_outer.py failed on {angle:g}, {size:g}: {r.stderr}")
    return json.loads(r.stdout)


def p_text(p):
    """' (p 0.45)' for a branch's p-value, '' where none is calibrated."""
    return "" if p is None else f" (p {p:.2g})"


def dist_err(d, angle):
    """The error of a record's distance from the load line (deg; None where not given)."""
    dist = d.get("distance_from_load_deg")
    return None if dist is None else dist - abs(angle)


def covered(interval, value):
    """Whether the interval [low, high] holds the value (None: no interval)."""
    return None if not interval else interval[0] <= value <= interval[1]


def on_pit(candidate, angle, d):
    """Whether a candidate's best run lies on the pit's branch (within half a ball spacing)."""
    return abs((candidate["best_run_deg"] - angle + 180) % 360 - 180) < 0.5 * d["ball_spacing_deg"]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", default=",".join(f"{a:g}:{s:g}" for a, s in CASES),
                    help="ANGLE:SIZE pairs (deg from the load, signed; deg of pit)")
    ap.add_argument("--rate", type=float, default=2e4)
    ap.add_argument("--bank", default="", help="the first stage's bank (default: locate_outer's)")
    ap.add_argument("--mismatch", nargs=3, metavar=("NAME", "RECORD_VALUE", "VALUE"),
                    help="the record's scene with the deck variable NAME at RECORD_VALUE, the "
                    "runs' at VALUE (e.g. F 336 320: the radial load 5 %% above what the user "
                    "states)")
    ap.add_argument("--length", type=float, default=LENGTH,
                    help="the records' length (s; default 0.3)")
    ap.add_argument("out")
    a = ap.parse_args(argv)
    if a.rate != 2e4 and not a.bank:
        sys.exit("locate_check: --rate other than 2e4 needs a --bank for that chain")
    if not 0.05 <= a.length <= 10:
        sys.exit(f"locate_check: --length expects seconds in [0.05, 10], got {a.length:g}")
    tag = ("" if a.rate == 2e4 else f"_r{a.rate:g}") + (
        f"_{a.mismatch[0]}{a.mismatch[1]}as{a.mismatch[2]}" if a.mismatch else "") + (
        "" if a.length == LENGTH else f"_len{a.length:g}")
    rows = []
    for c in a.cases.split(","):
        angle, size = (float(v) for v in c.split(":"))
        d = one(a.out, angle, size, a.rate, a.bank, a.mismatch, a.length)
        ok = d["branch_determined"]
        err = (d["position_deg"] - angle + 180) % 360 - 180 if ok else None
        ranked = sorted(d["candidates"], key=lambda x: x["chi2"])
        best = ranked[0]
        rows.append({"angle_deg": angle, "size_deg": size, "phase_deg": d["phase_deg"],
                     "position_deg": d["position_deg"], "error_deg": err,
                     "interval": d["position_interval_deg"], "determined": ok,
                     "within_15": ok and abs(err) <= 15, "margin": d.get("chi2_margin"),
                     "best_size_deg": best["best_run_size_deg"],
                     # not placed: the distance from the load line, either side, its
                     # interval, its error against the pit's and whether the interval holds it
                     "distance_deg": d.get("distance_from_load_deg"),
                     "distance_interval": d.get("distance_interval_deg"),
                     "distance_error_deg": dist_err(d, angle),
                     "distance_covered": covered(d.get("distance_interval_deg"), abs(angle)),
                     "mirror_pair": "mirror_positions_deg" in d,
                     "runs": sum(x["runs"] for x in d["candidates"]), "note": d["note"],
                     "fold_period": d["fold_period"], "margin_used": d["margin"],
                     "pulse_window": "-".join(f"{v:g}" for v in d["pulse_window"]),
                     # placed or not: the best run's angle and chi2, and the runner-up's
                     "best_run_deg": best["best_run_deg"], "best_chi2": best["chi2"],
                     "next_chi2": ranked[1]["chi2"] if len(ranked) > 1 else None,
                     # the p-values (locate_outer.own_branch_p(); None where not calibrated)
                     "best_p": best["p_value"],
                     "next_p": ranked[1]["p_value"] if len(ranked) > 1 else None,
                     # whether the best run lies on the pit's branch (placed or not): the
                     # calibration of locate_outer.OWN_BRANCH reads it
                     "best_on_pit_branch": on_pit(best, angle, d),
                     # the pit's own branch's best run (the p-values' calibration), wherever it
                     # ranks
                     "pit_branch_chi2": min((x["chi2"] for x in ranked if on_pit(x, angle, d)),
                                            default=None),
                     # the bins the chi2s are over (the pulse's window; own_branch_p() scales
                     # a chi2 to the calibration's)
                     "bins": d["bins"]})
        print(rows[-1], flush=True)
        common.write_csv(os.path.join(a.out, f"locate_check{tag}.csv"), rows,
                         quoted=("note", "interval", "distance_interval"))
    folds = "/".join(sorted({r["fold_period"] for r in rows}))
    margins = "/".join(f"{m:g}" for m in sorted({r["margin_used"] for r in rows}))
    windows = "/".join(sorted({r["pulse_window"] for r in rows}))
    lines = ["# The outer pit's branch on held-out places", "",
             f"Regenerated at {common.made_at()} by `studies/locate_check.py --cases={a.cases}"
             + (f" --rate {a.rate:g} --bank BANK" if a.rate != 2e4 else "")
             + (" --mismatch " + " ".join(a.mismatch) if a.mismatch else "")
             + ("" if a.length == LENGTH else f" --length {a.length:g}")
             + f" OUT` ({a.rate / 1e3:g} kHz, {a.length:g} s records, 16 bits, low noise, "
             "acquisition seed 7; the runs: seed 8; locate_outer.py's defaults: "
             f"{folds} folds compared over the pulse's window ({windows} of the period), margin "
             f"{margins}, zone 63 deg, --window 2 deg; the first stage's bank: "
             + (os.path.basename(a.bank) if a.bank else
                "the committed bank_outer_radial_r20000_low.txt") + ")"
             + (f"; the record's scene with {a.mismatch[0]} = {a.mismatch[1]}, the runs' (as the "
                f"user states it) {a.mismatch[2]}" if a.mismatch else "") + ".",
             "", "| pit (deg from load, size) | phase (deg) | placed (deg) | interval "
             "| error (deg) | not placed: distance from the load line (deg), interval, error "
             "| chi2 margin | best run (deg): chi2 (p), runner-up's | runs | note |",
             "|---" * 10 + "|"]
    for r in rows:
        iv = "-" if not r["interval"] else f"[{r['interval'][0]:.1f}, {r['interval'][1]:.1f}]"
        lines.append(
            f"| {r['angle_deg']:g}, {r['size_deg']:g} | {r['phase_deg']:.1f} | "
            + ("not determined" if not r["determined"] else f"{r['position_deg']:.2f}")
            + f" | {iv} | " + ("-" if r["error_deg"] is None else f"{r['error_deg']:+.2f}")
            + " | " + ("-" if r["distance_deg"] is None else
                       f"{r['distance_deg']:.2f} [{r['distance_interval'][0]:.1f}, "
                       f"{r['distance_interval'][1]:.1f}] {r['distance_error_deg']:+.2f}")
            + f" | {'-' if r['margin'] is None else format(r['margin'], '.0f')} | "
            f"{r['best_run_deg']:g}: {r['best_chi2']:.0f}{p_text(r['best_p'])}, "
            + ("-" if r["next_chi2"] is None else f"{r['next_chi2']:.0f}{p_text(r['next_p'])}")
            + f" | {r['runs']} | {r['note']} |")
    n = len(rows)
    placed = sum(r["determined"] for r in rows)
    right = sum(bool(r["within_15"]) for r in rows)
    wrong = placed - right
    mirror = sum(r["mirror_pair"] for r in rows)
    dist = [r for r in rows if r["distance_deg"] is not None]
    lines += ["", f"Placed {placed}/{n}; within 15 deg: {right}/{n}; placed on a wrong branch: "
              f"{wrong}/{n}; not determined: {n - placed}/{n}"
              + (f" (of which {mirror} a mirror pair)" if mirror else "") + "."]
    if dist:
        worst = max(abs(r["distance_error_deg"]) for r in dist)
        lines.append(
            f"Not placed but given as a distance from the load line, either side: {len(dist)}/{n}"
            f"; within 15 deg: {sum(abs(r['distance_error_deg']) <= 15 for r in dist)}"
            f"/{len(dist)} (the largest error {worst:.2f} deg); the interval holds the pit's "
            f"distance in {sum(r['distance_covered'] for r in dist)}/{len(dist)}, "
            f"{min(r['distance_interval'][1] - r['distance_interval'][0] for r in dist):.1f}-"
            f"{max(r['distance_interval'][1] - r['distance_interval'][0] for r in dist):.1f} "
            "deg wide.")
    with open(os.path.join(a.out, f"locate_check{tag}.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1:])

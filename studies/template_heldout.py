#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""A held-out check of the template-fit size (`diagnose --size-method template`): new
cases nobody looked at while the fit's constants were chosen, sized with every constant FROZEN
(the misfit weights 2 % and 5 us, the refusal threshold reduced chi-square 10, the committed
banks; no code in post/ changed, no bank rebuilt).

The cases are simulated as studies/sizing.py's (its simulate(): the deck inputs/bearing_6208,
50 um pits, 0.3 s after the sliding phase as studies/template_bank.py's TEND), acquired through
the study's chain (sizing.acquire_with_angle: 16 bits, low noise, the shaft-angle column) with an
acquisition noise seed other than the study's and the banks' (1), and sized with the study's own
template-method command line (template_bank.diagnose) on the committed 20 kHz low-noise banks
doc/report/sizing/template/bank_<defect>_<load>_r20000_low.txt (no 50 kHz bank is committed).

New sizes: halfway (in log size) between two of the bank's (12 % apart), none a bank's, a
study case's (0.3, 0.5, 1, 2, 3), an error run's (0.25, 0.6, 1.2, 2.2, 3.5) or a model curve's
size; the loads: fixed and force (inner, outer), radial inner at 45 deg on the ring (the study's:
90, 200, 330), radial outer at the load zone's centre (90 deg).

  studies/template_heldout.py [--seed 7] [--sizes 0.37,0.74,1.45,2.3]
                              [--kinds inner:radial:45,...] [--rate 2e4] [--noise low|high]
                              [--banks DIR] OUT

--rate, --noise and --banks (a folder of bank_<defect>_<load>_r<rate>_<noise>.txt, made by
studies/template_bank.py with those rates and noise levels) check the fit at another chain; the
committed banks are the 20 kHz low-noise ones.

Writes OUT/heldout.csv (sizing.csv's columns plus the refusal message) and OUT/heldout.md.
"""
import argparse
import contextlib
import io
import math
import os
import sys

import common
import sizing
import template_bank

BANKS = os.path.join(common.DOC, "report", "sizing", "template")
RATE, NOISE = 2e4, "low"
SIZES = [0.37, 0.74, 1.45, 2.3]
SEED = 7
# (defect, load, place on the ring, deg): the radial inner pit off the study's places
KINDS = [("inner", "fixed", 90.0), ("outer", "fixed", 90.0), ("inner", "force", 90.0),
         ("outer", "force", 90.0), ("inner", "radial", 45.0), ("outer", "radial", 90.0)]
DEFAULT_KINDS = ",".join(f"{d}:{l}:{p:g}" for d, l, p in KINDS)
STUDY = [0.3, 0.5, 1.0, 2.0, 3.0]


def nearest(size, bank):
    """The bank's size nearest `size` in log, and the distance (%)."""
    b = min(bank, key=lambda x: abs(math.log(x / size)))
    return b, 100 * (size / b - 1)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seed", type=int, default=SEED, help="acquisition noise seed (study: 1)")
    ap.add_argument("--sizes", default=",".join(f"{s:g}" for s in SIZES))
    ap.add_argument("--kinds", default=DEFAULT_KINDS,
                    help="defect:load:place triples")
    ap.add_argument("--rate", type=float, default=RATE, help="sampling rate (Hz)")
    ap.add_argument("--noise", choices=("low", "high"), default=NOISE)
    ap.add_argument("--banks", default=BANKS, help="folder of the banks (default: committed)")
    ap.add_argument("out")
    a = ap.parse_args(argv)
    rate, noise = a.rate, a.noise
    if a.seed == 1:
        sys.exit("template_heldout: seed 1 is the study's and the banks': take another")
    sizes = [float(s) for s in a.sizes.split(",")]
    for s in sizes:
        used = (template_bank.BANK_SIZES + template_bank.BANK_SIZES_ANGLES + STUDY +
                sizing.ERROR_SIZES + sizing.CURVE_SIZES + [sizing.CALIBRATION[1]])
        if any(abs(s - u) < 1e-9 for u in used):
            sys.exit(f"template_heldout: {s:g} deg is a bank's, case's or error run's size")
    os.makedirs(os.path.join(a.out, "acq"), exist_ok=True)
    rows = []
    kinds = [(k.split(":")[0], k.split(":")[1], float(k.split(":")[2]))
             for k in a.kinds.split(",")]
    for defect, load, place in kinds:
        bank = os.path.join(a.banks, f"bank_{defect}_{load}_r{rate:g}_{noise}.txt")
        if not os.path.exists(bank):
            sys.exit(f"template_heldout: no bank {bank} (--banks, --rate, --noise)")
        bank_sizes = template_bank.sizes_of(defect, load)
        for size in sizes:
            case = (defect, size, load, place)
            sim = sizing.simulate(a.out, case, template_bank.TEND)
            acq = os.path.join(a.out, "acq", f"heldout_{defect}_{size:g}_{load}_p{place:g}_"
                               f"r{rate:g}_{noise}_s{a.seed}.txt")
            if not os.path.exists(acq):
                sizing.acquire_with_angle(sim, load, rate, noise, acq, seed=a.seed)
            err = io.StringIO()
            with contextlib.redirect_stderr(err):
                d = template_bank.diagnose(a.out, sim, acq, defect, bank)
            r = sizing.row(d, case, rate, noise, "template")
            if d.get("position_reference") == "load direction" and r["position_est_deg"] \
                    is not None and not d.get("position_modulo_deg"):
                # as template_bank.py: the outer pit's branch resolved by the fit's angle, the
                # error on the true angle from the load direction
                r["position_error_deg"] = (r["position_est_deg"] - (place - 90) + 180) % 360 - 180
            r["position_modulo"] = bool(d.get("position_modulo_deg"))
            r["nearest_bank_deg"], r["from_bank_pct"] = nearest(size, bank_sizes)
            r["note"] = "" if r["size_deg_est"] is not None else (
                d.get("size_method") or err.getvalue().strip() or d.get("defect", ""))
            r["fit"] = d.get("size_method", "")
            print(f"{defect} {size:g} {load} p{place:g}: {r['size_deg_est']} [{r['low']}, "
                  f"{r['high']}] covers {r['covers']} {r['note']}", flush=True)
            rows.append(r)
    common.write_csv(os.path.join(a.out, "heldout.csv"), rows, quoted=("note", "fit"))
    n = len(rows)
    within = sum(r["error_pct"] is not None and abs(r["error_pct"]) <= 15 for r in rows)
    covered = sum(bool(r["covers"]) for r in rows)
    lines = ["# Template-fit sizing: held-out check (constants frozen)", "",
             f"Regenerated at {common.made_at()} by `studies/template_heldout.py --seed {a.seed} --sizes {a.sizes}"
             + ("" if a.kinds == DEFAULT_KINDS else f" --kinds {a.kinds}")
             + ("" if (rate, noise) == (RATE, NOISE) else f" --rate {rate:g} --noise {noise}")
             + ("" if a.banks == BANKS else " --banks DIR") +
             f" OUT` ({rate:g} Hz, {noise} noise, 16 bits, acquisition seed {a.seed}; the study "
             "and the banks: seed 1), on "
             + ("the committed banks" if a.banks == BANKS else "banks made by "
                "studies/template_bank.py for that chain") +
             f" `bank_<defect>_<load>_r{rate:g}_{noise}.txt`; no bank rebuilt for this check.",
             "", "| load | defect | place (deg) | size (deg) | nearest bank size | estimate | "
             "error | interval | covered | position error (deg) | note |", "|---" * 11 + "|"]
    for r in rows:
        est = "not sized" if r["size_deg_est"] is None else f"{r['size_deg_est']:.3g}"
        iv = common.interval_text(r["low"], r["high"])
        e = "-" if r["error_pct"] is None else f"{r['error_pct']:+.1f} %"
        pe = "-" if r["position_error_deg"] is None or r["load"] != "radial" else \
            f"{r['position_error_deg']:+.1f}" + (" mod" if r["position_modulo"] else "")
        lines.append(f"| {r['load']} | {r['defect']} | {r['position_deg']:g} | {r['size_deg']:g} "
                     f"| {r['nearest_bank_deg']:g} ({r['from_bank_pct']:+.1f} %) | {est} | {e} | "
                     f"{iv} | {'yes' if r['covers'] else 'no'} | {pe} | {r['note']} |")
    lines += ["", f"Within 15 %: {within}/{n}; interval covers the true size: {covered}/{n} "
              "(one not sized counts as neither). Position error: radial load only (the inner "
              "pit's angle on the ring from the shaft angle; the outer pit's from the load "
              "direction, 'mod': known modulo the ball spacing).", ""] + sizing.summary(rows)
    with open(os.path.join(a.out, "heldout.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1:])

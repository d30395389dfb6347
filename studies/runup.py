#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The run-up study: the SKF 6208 from 200 to 500 rad/s over 0.3 s with a 1 deg
inner-race defect. The plain spectrum smears the BPFI line over the band the speed sweeps;
resampled at constant shaft angle (ohmdem-post orders, and diagnose, which does it by itself
when the speed varies) the defect is one line at the BPFI order 7.851. Writes into OUT:
  signal.txt, run.json       the run
  spectrum.png               the plain spectrum (smeared)
  spectrogram.png            time-frequency map, the defect frequencies following the speed
  orders.csv                 the order spectrum's peaks
  runup.md                   the numbers
"""
import argparse
import json
import os

import common


def analyse(out, bearing):
    d = json.load(open(os.path.join(out, "diagnose.json")))
    bpfi = bearing.bpfi_order()
    rows = [l.split(",") for l in open(os.path.join(out, "orders.csv")) if l[0].isdigit()]
    near = [(float(r[1]), float(r[2]), float(r[3])) for r in rows
            if abs(float(r[1]) / bpfi - 1) < 0.02]
    order = d["frequency_hz"] / d["shaft_hz"]
    two_pi = 2 * 3.141592653589793
    lines = ["# Run-up study, machado2014 (the paper's model of an SKF 6208) (ohmdem)", "",
             f"Regenerated at {common.made_at()} by `studies/runup.py OUT`: the inner ring from 200 to 500 "
             "rad/s over 0.3 s (`-var omega_start 200 -var ramp 0.3`), then 500 rad/s to 0.35 s; a "
             "1 deg inner-race pit. The analysis window starts after the sliding phase (0.015 s).", "",
             "![plain spectrum](spectrum.png)", "",
             "The plain spectrum spreads the defect over the band the speed sweeps: BPFI goes from "
             f"{200 / two_pi * bpfi:.0f} Hz to {500 / two_pi * bpfi:.0f} Hz.", "",
             "![spectrogram](spectrogram.png)", "",
             "Resampled at constant shaft angle (`ohmdem-post orders`, from the `angle_inner` "
             "column):", "", "| order | amplitude (ohm) | prominence (dB) |", "|---|---|---|"]
    lines += [f"| {o:.4f} | {a:.3g} | {p:.1f} |" for o, a, p in near[:3]]
    lines += ["", f"`ohmdem-post diagnose` switches to the order domain by itself (domain: "
              f"{d['domain']}) and reads **{d['defect']}** at order {order:.5f} against the "
              f"kinematic {bpfi:.5f} ({order / bpfi - 1:+.1e}).", ""]
    open(os.path.join(out, "runup.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out", help="output folder")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    out = os.path.realpath(a.out)
    common.run(common.deck_command(common.BEARING_DECK, [
        "-var", "out", out, "-var", "tend", "0.35", "-var", "omega_start", "200",
        "-var", "omega", "500", "-var", "ramp", "0.3", "-var", "defect", "inner",
        "-var", "size", "1", "-log", os.path.join(out, "log.liggghts"), "-screen", "none"]),
        who="runup")
    sig = os.path.join(out, "signal.txt")
    common.run([common.POST, "plot", "--kind", "spectrum", "--from", "0.02", "--logy", "--fmax",
                "2000", "--harmonics", "2", "--output", os.path.join(out, "spectrum.png"),
                "--title", "Run-up 200 -> 500 rad/s, 1 deg inner defect: plain spectrum (lines "
                "marked at 500 rad/s)", sig], who="runup")
    common.run([common.POST, "plot", "--kind", "spectrogram", "--from", "0.02", "--segment",
                "65536", "--fmax", "2000", "--harmonics", "2", "--output",
                os.path.join(out, "spectrogram.png"), sig], who="runup")
    common.run([common.POST, "orders", "--format", "csv", "--order-min", "1", "--peaks", "40",
                "--output", os.path.join(out, "orders.csv"), sig], who="runup")
    common.post_to(os.path.join(out, "diagnose.json"), ["diagnose", "--format", "json", sig],
                   who="runup")
    analyse(out, common.Bearing("machado2014"))


if __name__ == "__main__":
    main()

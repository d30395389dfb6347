#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""A run-up of the bearing deck: the inner ring from 200 to 500 rad/s over 0.3 s with
a 1 deg inner-race defect, through omega_start and through an equal-style variable. The shaft
angle column is the integral of the speed column; diagnose
resamples at constant shaft angle and finds the inner defect at the BPFI order 7.8515 (6208:
Nb/2 (1 + d/D) with d = 12.6 mm, D = 60.6 mm); a ramp from omega to omega gives the constant
run's bits.
Usage: runup_tests.py --exe OHMDEM --post OHMDEM_POST --src SOURCE_DIR"""
import argparse
import json
import os
import subprocess
import tempfile

import numpy as np

from deck_checks import check, finish, read_signal

BPFI_ORDER = 13 / 2 * (1 + 0.0126 / 0.0606)  # 7.851485


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--post", required=True)
    p.add_argument("--src", required=True)
    a = p.parse_args()
    deck = os.path.join(a.src, "inputs", "bearing_6208", "in.bearing")

    profile = os.path.join(a.src, "inputs", "bearing_6208", "in.speed_profile")

    def run(out, in_file=deck, **var):
        cmd = [a.exe, "-in", in_file, "-var", "out", out, "-log", "none", "-screen", "none"]
        if in_file != deck:
            cmd += ["-var", "bearing_deck", deck]
        for k, v in var.items():
            cmd += ["-var", k, str(v)]
        subprocess.run(cmd, check=True)
        return out

    def diagnose(out):
        r = subprocess.run([a.post, "diagnose", "--format", "json",
                            os.path.join(out, "signal.txt")], capture_output=True, text=True)
        d = json.loads(r.stdout) if r.returncode == 0 else {}
        return d, d.get("frequency_hz", 0) / d.get("shaft_hz", 1), r.stderr.strip()

    with tempfile.TemporaryDirectory(prefix="ohmdem_runup_") as wd:
        out = run(os.path.join(wd, "runup"), tend=0.35, omega=500, omega_start=200, ramp=0.3,
                  defect="inner", size=1)
        sig = read_signal(os.path.join(out, "signal.txt"))
        t, ang, w = sig["time"], sig["angle_inner"], sig["omega_inner"]
        expected_w = np.where(t < 0.3, 200 + 300 * t / 0.3, 500.0)
        check(np.max(np.abs(w - expected_w)) < 1e-9 * 500,
              "omega_inner follows the ramp 200 -> 500 rad/s over 0.3 s")
        # the angle integrates the speed at mid-step: the trapezoid rule of the column is exact
        # for a linear ramp up to the kink at 0.3 s
        trap = np.concatenate([[ang[0]], ang[0] + np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))])
        err = np.max(np.abs(ang - trap))
        check(err < 1e-6, f"angle_inner is the integral of omega_inner (max difference {err:.1e} rad)")
        meta = json.load(open(os.path.join(out, "run.json")))
        check(meta["omega_start"] == 200 and meta["ramp"] == 0.3 and meta["omega_inner"] == 500,
              "run.json records the speed profile")
        d, order, err_text = diagnose(out)
        check(d.get("defect") == "inner" and d.get("domain") == "orders",
              f"diagnose: {d.get('defect')} in the {d.get('domain')} domain {err_text}")
        check(abs(order / BPFI_ORDER - 1) < 0.005,
              f"BPFI order {order:.5f} against {BPFI_ORDER:.5f} ({order / BPFI_ORDER - 1:+.2e})")

        # a ramp from the speed to itself is the constant speed, to the bit
        const = run(os.path.join(wd, "const"), tend=0.003, omega=500)
        flat = run(os.path.join(wd, "flat"), tend=0.003, omega=500, omega_start=500, ramp=0.3)
        same = open(os.path.join(const, "signal.txt"), "rb").read() == \
            open(os.path.join(flat, "signal.txt"), "rb").read()
        check(same, "omega_start = omega: signal.txt identical to the constant-speed run")

        # omega and F from equal-style variables (inputs/bearing_6208/in.speed_profile): constant
        # variables give the constants' bits; a ramp formula drives a run-up like omega_start
        var_const = run(os.path.join(wd, "var_const"), profile, tend=0.003, wdef="500", fdef="320")
        same = open(os.path.join(const, "signal.txt"), "rb").read() == \
            open(os.path.join(var_const, "signal.txt"), "rb").read()
        check(same, "omega v_w and force v_f of constant variables: signal.txt identical")
        meta = json.load(open(os.path.join(var_const, "run.json")))
        check(meta["omega_inner"] == 500 and meta["omega_input"] == "v_wprofile" and
              meta["F"] == 320 and meta["F_input"] == "v_fprofile",
              "run.json: the variables' values at the start and their names")
        ramp = run(os.path.join(wd, "var_ramp"), profile, tend=0.35, defect="inner", size=1,
                       wdef="(step*dt<0.3)*(200+1000*step*dt)+(step*dt>=0.3)*500")
        sig = read_signal(os.path.join(ramp, "signal.txt"))
        t, w = sig["time"], sig["omega_inner"]
        # evaluated at the start of each step: step = t/dt
        expected_w = np.where(t < 0.3, 200 + 1000 * t, 500.0)
        check(np.max(np.abs(w - expected_w)) < 1e-6,
              "omega v_NAME: the speed column follows the variable's formula")
        d, order, err_text = diagnose(ramp)
        check(d.get("defect") == "inner" and abs(order / BPFI_ORDER - 1) < 0.005,
              f"variable run-up: {d.get('defect')} at order {order:.5f} "
              f"({order / BPFI_ORDER - 1:+.2e}) {err_text}")
    finish()


if __name__ == "__main__":
    main()

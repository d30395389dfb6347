#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Defects as contact masks (issue: defects), on the SKF 6208 deck.

Checks against the kinematic frequencies (Harris), the duty of a rectangle train
d = Nb*dphi/360 deg (inner race), the displacement-control level R0*Nb/(Nb-1), and the
rectangle-train kurtosis (1 - 3d(1-d))/(d(1-d)); prints the measured curves for the report.
Usage: defect_tests.py TEST --exe OHMDEM --src SOURCE_DIR
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

from deck_checks import check, finish, read_signal

DB, DEXT, DINN, NB = 0.0126, 0.0732, 0.048, 13
D = (DEXT + DINN) / 2
T0, T1 = 0.015, 0.12  # analysis window: after the sliding phase (11.4 ms), 0.105 s long
F = 320.0
def kinematic(omega):
    """Harris, zero contact angle: FTF, BPFO, BPFI, BSF (Hz) for shaft speed omega (rad/s)."""
    fr = omega / (2 * math.pi)
    ftf = fr / 2 * (1 - DB / D)
    return {"ftf": ftf, "bpfo": NB * ftf, "bpfi": NB * fr / 2 * (1 + DB / D),
            "bsf": D / (2 * DB) * fr * (1 - (DB / D) ** 2)}


def run(exe, src, wd, name, **var):
    out = os.path.join(wd, name)
    os.makedirs(out, exist_ok=True)
    cmd = [exe, "-in", os.path.join(src, "inputs", "bearing_6208", "in.bearing"), "-log",
           os.path.join(out, "log.txt"), "-screen", "none", "-var", "out", out,
           "-var", "tend", str(T1)]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)}\n{res.stdout[-2000:]}{res.stderr[-2000:]}")
    sig = read_signal(os.path.join(out, "signal.txt"))
    keep = sig["time"] > T0
    return {n: v[keep] for n, v in sig.items()}


def events(sig, r0, jump=0.04, merge=5e-4):
    """Times of the contact breaks seen in R: upward crossings of R0*(1 + jump) (a broken path
    raises R by 1/(Nb-1) = 8.3 % at once), merged when closer than `merge`: one passage can
    cross several times (break, relief by the ring, re-entry over the edge). 0.5 ms is longer
    than any passage here (88 us per degree on the outer race) and shorter than the shortest
    period (BPFI: 1.6 ms at 500 rad/s)."""
    high = sig["R"] > r0 * (1 + jump)
    out = []
    for t in sig["time"][1:][np.diff(high.astype(int)) == 1]:
        if not out or t - out[-1] > merge:
            out.append(t)
    return np.array(out)


def repetition(ev):
    return (len(ev) - 1) / (ev[-1] - ev[0]) if len(ev) > 2 else 0.0


def pearson_kurtosis(x):
    x = x - x.mean()
    return np.mean(x**4) / np.mean(x**2) ** 2


def test_frequencies(exe, src, wd):
    healthy = run(exe, src, wd, "healthy")
    r0 = np.median(healthy["R"])
    k = kinematic(500.0)
    expect = {"inner": ("BPFI", k["bpfi"]), "outer": ("BPFO", k["bpfo"]),
              "ball": ("2*BSF", 2 * k["bsf"])}
    for defect, (label, f_ref) in expect.items():
        sig = run(exe, src, wd, defect, defect=defect, size=1.0)
        ev = events(sig, r0)
        f = repetition(ev)
        check(abs(f / f_ref - 1) < 0.01,
              f"{defect} defect: disturbances of R repeat at {f:.2f} Hz, {label} = {f_ref:.2f} Hz "
              f"({f / f_ref - 1:+.2%}, {len(ev)} passages in {T1 - T0:.3f} s)")
        check(np.all(np.isfinite(sig["R"])), f"{defect} defect: R finite at every step")
        # Re-entry: the ball climbs out of the pit over its edge, a real shock. Bound: a ball
        # of mass m meeting the edge at v = 6 m/s (ball set speed) times the edge slope
        # sqrt(2h/r) at the floor depth h = 5 um hits the race at about 0.24 m/s: Hertz
        # impact F = K*delta^1.5 with delta = (5 m v^2/(4K))^(2/5) gives ~190 N, 7.5x the
        # nominal F/Nb. A literal mask (no floor) gives kilonewtons.
        nominal = F / NB
        peak = max(sig["fn_inner_max"].max(), sig["fn_outer_max"].max())
        check(peak < 10 * nominal,
              f"{defect} defect: largest contact force {peak:.1f} N = {peak / nominal:.1f}x the "
              f"nominal {nominal:.1f} N (< 10x: geometric re-entry over the pit edge)")
    # Cage: the broken bar is mechanical only (the cage insulates).
    sig = run(exe, src, wd, "cage", defect="cage")
    dev = np.max(np.abs(sig["R"] / r0 - 1))
    check(dev < 1e-4, f"cage defect: R stays healthy (max |R/R0 - 1| = {dev:.1e})")
    # What the cage does: its speed and its contacts, and at which frequency they vary.
    w = sig["omega_cage"] - sig["omega_cage"].mean()
    spec = np.abs(np.fft.rfft(w * np.hanning(len(w))))
    freqs = np.fft.rfftfreq(len(w), sig["time"][1] - sig["time"][0])
    fpk = freqs[1:][np.argmax(spec[1:])]
    print(f"     cage defect: the ball of the broken pocket leans on the missing bar "
          f"({np.mean(sig['n_masked'] > 0):.0%} of the time); cage speed "
          f"{sig['omega_cage'].mean():.3f} +- {sig['omega_cage'].std():.3f} rad/s, dominant "
          f"frequency of its variation {fpk:.1f} Hz (FTF = {k['ftf']:.2f} Hz), "
          f"cage contacts {sig['n_contacts_cage'].mean():.2f} on average")


def test_sizes(exe, src, wd):
    sizes = [0.5, 1.0, 1.5, 2.0, 3.0]
    for load in ("fixed", "force"):
        rows = []
        for size in sizes:
            # The defect appears after the settling (fixed: the radius of healthy steady
            # rolling is held from tsettle = 0.014 s), so all sizes share the same ring.
            sig = run(exe, src, wd, f"{load}_{size}", defect="inner", size=size, load=load,
                      dstart=T0)
            if not rows:
                r0 = sig["R"][0]  # healthy, at T0 (the defect appears at T0)
            duty_geo = NB * size / 360.0
            broken = sig["n_masked"] > 0
            duty = broken.mean()
            one = sig["n_masked"] == 1
            R = sig["R"]
            rows.append((size, duty_geo, duty, R.mean(), math.sqrt(np.mean(R**2)),
                         pearson_kurtosis(R), np.median(R[one]) / r0 if one.any() else math.nan,
                         R.min() / r0, R.max() / r0))
            check(abs(duty / duty_geo - 1) < 0.03,
                  f"{load}, inner {size} deg: a path is broken {duty:.4f} of the time, "
                  f"Nb*dphi/360 = {duty_geo:.4f}")
        rows = np.array(rows)
        print(f"     {load}: size  d_geo   d_meas  mean(R)  rms(R)  kurtosis  rect.kurt  "
              f"R(1 broken)/R0  Rmin/R0  Rmax/R0")
        for s_, dg, dm, mean, rms, ku, r1, rmin, rmax in rows:
            rect = (1 - 3 * dm * (1 - dm)) / (dm * (1 - dm))
            print(f"     {load}: {s_:4.1f}  {dg:.4f}  {dm:.4f}  {mean:.5f}  {rms:.5f}  {ku:8.2f}  "
                  f"{rect:8.2f}  {r1:.5f}  {rmin:.4f}  {rmax:.4f}")
        d = rows[:, 2]
        if load == "fixed":
            lvl = rows[:, 6]
            check(np.all(np.abs(lvl / (NB / (NB - 1)) - 1) < 0.005),
                  f"fixed ring: while one path is broken R = R0*Nb/(Nb-1) = {NB / (NB - 1):.5f} R0 "
                  f"(measured {lvl.min():.5f}..{lvl.max():.5f})")
            slope = np.polyfit(d, rows[:, 3], 1)[0]
            ref = r0 / (NB - 1)  # mean R = R0 (1 + d/(Nb-1)) for a rectangle train
            check(abs(slope / ref - 1) < 0.05,
                  f"fixed ring: mean R grows linearly with d, slope {slope:.5f} ohm vs "
                  f"R0/(Nb-1) = {ref:.5f} ohm")
            rms_slope = np.polyfit(d, rows[:, 4], 1)[0]
            check(abs(rms_slope / ref - 1) < 0.05,
                  f"fixed ring: RMS of R grows linearly with d, slope {rms_slope:.5f} ohm")
            ku = rows[:, 5]
            rect = (1 - 3 * d * (1 - d)) / (d * (1 - d))
            err = np.max(np.abs(ku / rect - 1))
            check(err < 0.1, f"fixed ring: kurtosis follows the rectangle train "
                  f"(1-3d(1-d))/(d(1-d)) within {err:.1%}: it falls as the defect grows")
        else:
            check(np.all(rows[:, 7] < 0.995),
                  "force ring: while a ball is off, the others take the load back and R falls "
                  f"below R0 (min R/R0 = {rows[:, 7].min():.4f}; 12 balls carrying F: "
                  f"{(NB / (NB - 1)) * ((NB - 1) / NB) ** (4 / 3):.4f})")


def test_diagnose(exe, src, wd, post):
    """ohmdem-post diagnose on the engine's own signals: each defect kind identified, the
    healthy bearing and the (insulating) cage defect seen as no electrical defect."""
    import json
    for defect, expected in (("none", "none"), ("inner", "inner"), ("outer", "outer"),
                             ("ball", "ball"), ("cage", "none")):
        run(exe, src, wd, f"diag_{defect}", defect=defect, size=1.0)
        path = os.path.join(wd, f"diag_{defect}", "signal.txt")
        res = subprocess.run([post, "diagnose", "--format", "json", path], capture_output=True,
                             text=True)
        if res.returncode != 0:
            sys.exit(f"FAIL: ohmdem-post diagnose {path}: {res.stderr}")
        j = json.loads(res.stdout)
        size = j.get("size_deg")
        what = f", size estimate {size:.2f} deg" if size is not None else ""
        check(j["defect"] == expected,
              f"{defect} run: diagnosed '{j['defect']}' (score {j['score']:.2f}, "
              f"{j['frequency_hz']} Hz{what}); expected '{expected}'")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test")
    p.add_argument("--exe", required=True)
    p.add_argument("--src", required=True)
    p.add_argument("--post", help="ohmdem-post, for the diagnose test")
    a = p.parse_args()
    with tempfile.TemporaryDirectory(prefix=f"ohmdem_defect_{a.test}_") as wd:
        if a.test == "diagnose":
            test_diagnose(os.path.abspath(a.exe), os.path.abspath(a.src), wd,
                          os.path.abspath(a.post))
        else:
            {"frequencies": test_frequencies, "sizes": test_sizes}[a.test](
                os.path.abspath(a.exe), os.path.abspath(a.src), wd)
    finish()


if __name__ == "__main__":
    main()

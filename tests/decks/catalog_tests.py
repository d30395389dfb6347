#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Deck-level tests of the bearing catalog (inputs/bearings, issue: any deep-groove ball bearing).

Each test runs build/ohmdem on inputs/bearing_6208/in.bearing with -var bearing NAME and checks
the result against numbers we did not make: CWRU's published defect multiples and the lines that
ohmdem-post finds in CWRU's measured records, Stribeck's load distribution, the closed-form
parallel sum of the ball resistances. Geometry comes from the run's own run.json.
The places and injection tests run the deck as a user would: from its own folder, the
repository root and elsewhere with no OHMDEM_CATALOG, and with names a shell would run.
Usage: catalog_tests.py TEST --exe OHMDEM --post OHMDEM_POST --src SOURCE_DIR
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

import deck_checks
from deck_checks import check, finish

CWRU = "6205-2RS_JEM"
# CWRU's test speed (rpm) of the records compared below, as rad/s for the deck.
RPM = 1797.0
OMEGA = RPM * 2 * math.pi / 60
# CWRU Bearing Data Center, drive-end bearing: defect frequencies as multiples of the shaft
# frequency (inner 5.4152, outer 3.5848, cage 0.39828, rolling element 4.7135 = 2 BSF).
CWRU_MULTIPLES = {"inner": 5.4152, "outer": 3.5848, "ball": 4.7135, "cage": 0.39828}
# CWRU records of ../shared/data/bearing-real recorded at 1797 rpm (its README); their defect
# kind is what ohmdem-post diagnose finds (the README does not say).
REAL_RECORDS = ["sig01", "sig06", "sig07", "sig13"]
# The CWRU 6205 at 188 rad/s rolls after about 10 ms; its smaller balls want a smaller step
# than the 6208's 1e-5 s limit: 5e-6 s.
DT = 5e-6


class Runner:
    def __init__(self, exe, src, workdir):
        self.exe, self.src, self.workdir = exe, src, workdir
        self.deck = os.path.join(src, "inputs", "bearing_6208", "in.bearing")

    def run(self, name, **var):
        out = os.path.join(self.workdir, name)
        os.makedirs(out, exist_ok=True)
        cmd = [self.exe, "-in", self.deck, "-log", os.path.join(out, "log.txt"),
               "-screen", "none", "-var", "out", out,
               "-var", "catalog", os.path.join(self.src, "inputs", "bearings")]
        for k, v in var.items():
            cmd += ["-var", k, str(v)]
        res = subprocess.run(cmd, cwd=out, capture_output=True, text=True)
        if res.returncode != 0:
            log = open(os.path.join(out, "log.txt")).read() if os.path.exists(
                os.path.join(out, "log.txt")) else ""
            sys.exit(f"FAIL: {' '.join(cmd)} exited {res.returncode}\n{res.stdout[-3000:]}"
                     f"\n{res.stderr[-3000:]}\n{log[-3000:]}")
        meta = json.load(open(os.path.join(out, "run.json")))
        return out, meta


def read_signal(folder):
    return deck_checks.read_signal(os.path.join(folder, "signal.txt"))


def ftf_omega(meta):
    """Cage angular speed of pure rolling (Harris, zero contact angle): 2*pi*FTF."""
    return meta["omega_inner"] / 2 * (1 - meta["db"] / meta["dp"])


def rolling_from(sig, meta, tol=0.01):
    """First time after which the ball set orbits within tol of 2*pi*FTF (None: never)."""
    bad = np.nonzero(np.abs(sig["omega_balls"] / ftf_omega(meta) - 1) > tol)[0]
    if len(bad) == 0:
        return sig["time"][0]
    return None if bad[-1] + 1 >= len(sig["time"]) else sig["time"][bad[-1] + 1]


def pulse_rate(sig, t0):
    """Defect passes per second: onsets of masked contacts after t0, (N - 1)/(t_N - t_1)."""
    t, n = sig["time"], sig["n_masked"]
    on = t[1:][(n[1:] > 0) & (n[:-1] == 0)]
    on = on[on > t0]
    return (len(on) - 1) / (on[-1] - on[0]) if len(on) > 2 else None, len(on)


def test_kinematics(r, post, src):
    fr = OMEGA / (2 * math.pi)
    sim = {}
    for kind in ("inner", "outer", "ball"):
        out, meta = r.run(f"cwru_{kind}", bearing=CWRU, omega=repr(OMEGA), dt=DT, tend=0.12,
                          defect=kind, size=1.0)
        check(meta["bearing"] == CWRU and meta["nb"] == 9,
              f"{kind}: run.json names {meta['bearing']} with its {meta['nb']} balls")
        sig = read_signal(out)
        t_roll = rolling_from(sig, meta)
        check(t_roll is not None and t_roll < 0.03,
              f"{kind}: rolling from t = {t_roll} s (ball set within 1 % of 2*pi*FTF)")
        if t_roll is None:
            continue
        if kind == "inner":
            w = sig["omega_balls"][sig["time"] > t_roll + 0.005].mean()
            ftf = w / (2 * math.pi)
            ref = CWRU_MULTIPLES["cage"] * fr
            check(abs(ftf / ref - 1) < 5e-3,
                  f"FTF {ftf:.4f} Hz = {ftf / fr:.5f} fr vs CWRU 0.39828 fr ({ftf / ref - 1:+.3%})")
        f, n = pulse_rate(sig, t_roll + 0.005)
        ref = CWRU_MULTIPLES[kind] * fr
        name = {"inner": "BPFI", "outer": "BPFO", "ball": "2xBSF"}[kind]
        check(f is not None and abs(f / ref - 1) < 5e-3,
              f"{name} from {n} defect passes: {f:.4f} Hz = {f / fr:.5f} fr vs CWRU "
              f"{CWRU_MULTIPLES[kind]} fr = {ref:.4f} Hz ({f / ref - 1:+.3%})")
        sim[kind] = f
    if "ball" in sim:
        print(f"     BSF = {sim['ball'] / 2 / fr:.5f} fr (CWRU 4.7135/2 = 2.35675 fr)")

    # The lines ohmdem-post finds in CWRU's measured records of the same defect kind.
    real = os.path.join(src, "..", "shared", "data", "bearing-real")
    if not os.path.isdir(real):
        print(f"     skipped: no measured records in {real}")
        return
    for rec in REAL_RECORDS:
        res = subprocess.run([post, "diagnose", os.path.join(real, rec + ".txt"), "--rate", "12000",
                              "--rpm", str(RPM), "--bearing", CWRU, "--format", "json"],
                             capture_output=True, text=True)
        check(res.returncode == 0, f"ohmdem-post diagnose {rec}: exit {res.returncode} "
              f"{res.stderr.strip()}")
        if res.returncode != 0:
            continue
        d = json.loads(res.stdout)
        kind = d["defect"]
        if kind not in sim:
            print(f"     {rec}: diagnosed '{kind}', no simulated counterpart")
            continue
        found = d["frequency_hz"]
        # 1 %: the records' speed is the one written down (the README: the true speed may
        # differ by a few rpm) and a real bearing slips; diagnose itself searches +-2 %.
        check(abs(sim[kind] / found - 1) < 0.01,
              f"{rec} (measured, {RPM:g} rpm): ohmdem-post finds {kind} at {found:.3f} Hz; "
              f"simulated {sim[kind]:.3f} Hz ({sim[kind] / found - 1:+.2%})")


def stribeck_factor(nb):
    """Q_max = factor * Fr / Nb for zero clearance, a ball on the load line: Stribeck's sum
    over the loaded balls of cos(psi)^(5/2) (point contact; Harris, Rolling Bearing Analysis,
    ch. 7): factor = Nb / sum."""
    c = np.cos(2 * np.pi * np.arange(nb) / nb)
    return nb / np.sum(c[c > 0] ** 2.5)


def test_radial(r):
    for name, fr_load in ((CWRU, 1000.0), ("machado2014", 2000.0)):
        # The outer ring is pushed along -y: its top part meets the balls there (ball 1 at 90°).
        out, meta = r.run(f"radial_{name}", bearing=name, load="radial", F=fr_load, omega=0.0,
                          phase=90.0, tend=0.004, nout=10)
        log = open(os.path.join(out, "log.txt")).read()
        m = re.search(r"^RADIAL_QMAX (\S+)", log, re.M)
        check(m is not None, f"{name}: maximum ball load reported")
        if m is None:
            continue
        nb = meta["nb"]
        got = float(m.group(1)) / (fr_load / nb)
        ref = stribeck_factor(nb)
        check(abs(got / ref - 1) < 0.02,
              f"{name}, {nb} balls: Q_max = {got:.4f}*Fr/Nb vs Stribeck {ref:.4f}*Fr/Nb "
              f"({got / ref - 1:+.2%})")


def greenwood_area(fn, A, B, E_eff):
    """Paper eqs. 2-5 (Greenwood 1985): rigid Hertz contact area from the normal force."""
    r_eff = (A * B * (A + B) / 2) ** (-1 / 3)
    c = (3 * fn * r_eff / (4 * E_eff)) ** (1 / 3)
    return math.pi * c * c


def test_resistance(r):
    # Each ball is one eq. 1 resistor between its outer and inner contact points, which face
    # each other (1 - cos = 2): C = gamma*S_out*S_in/(4*V), with the areas of this bearing's
    # own curvatures; the Nb balls carry equal loads, so R = 1/(Nb*C).
    out, meta = r.run("resistance_cwru", bearing=CWRU, omega=repr(OMEGA), dt=DT, tend=0.03,
                      nout=10)
    sig = read_signal(out)
    t_roll = rolling_from(sig, meta)
    check(t_roll is not None, "the CWRU 6205 rolls")
    if t_roll is None:
        return
    steady = sig["time"] > t_roll + 0.002
    R = sig["R"][steady]
    rb = meta["db"] / 2
    E_eff = 2e11 / (2 * (1 - 0.3**2))
    gamma = 5.88e7
    V = 4 / 3 * math.pi * rb**3
    s_in = greenwood_area(sig["fn_inner_mean"][steady], 1 / rb + 2 / meta["dinn"],
                          1 / rb - 1 / meta["rc_inn"], E_eff)
    s_out = greenwood_area(sig["fn_outer_mean"][steady], 1 / rb - 2 / meta["dext"],
                           1 / rb - 1 / meta["rc_ext"], E_eff)
    r_ref = 1 / (meta["nb"] * gamma * s_in * s_out / (4 * V))
    err = np.max(np.abs(R / r_ref - 1))
    print(f"     CWRU 6205 healthy R = {R.mean():.6f} ohm at F = {meta['F']:.4g} N, "
          f"{OMEGA:.2f} rad/s")
    check(err < 1e-9, f"R equals the parallel sum of {meta['nb']} eq. 1 ball resistors with "
          f"the 6205's Hertz areas (max rel. error {err:.1e})")
    fsum = sig["fn_outer_sum"][steady].mean()
    check(abs(fsum / meta["F"] - 1) < 1e-3,
          f"outer reactions {fsum:.4f} N balance the bearing's default F = {meta['F']:.4f} N")


def test_custom(r):
    # A bearing given by its dimensions alone runs exactly as the same catalog entry.
    dims = {}
    for line in open(os.path.join(r.src, "inputs", "bearings", CWRU)):
        m = re.match(r"\s*variable\s+(\w+)\s+index\s+(\S+)", line)
        if m:
            dims[m.group(1)] = m.group(2)
    a, ma = r.run("named", bearing=CWRU, tend=0.002, nout=10)
    b, mb = r.run("custom", bearing="custom", tend=0.002, nout=10, **dims)
    same = open(os.path.join(a, "signal.txt")).read() == open(os.path.join(b, "signal.txt")).read()
    check(same, "custom with the catalog's dimensions = the catalog entry (identical signal.txt)")
    check(ma["bearing"] == CWRU and mb["bearing"] == "custom",
          f"run.json names them {ma['bearing']!r} and {mb['bearing']!r}")
    # One dimension overridden: the run is custom, and run.json has what ran.
    c, mc = r.run("override", bearing=CWRU, tend=0.002, nout=10, Rcinn=0.0042)
    check(mc["bearing"] == "custom" and mc["catalog_name"] == CWRU and mc["rc_inn"] == 0.0042,
          f"-var Rcinn 0.0042 on {CWRU}: run.json bearing {mc['bearing']!r}, rc_inn {mc['rc_inn']}")
    # The default stays the paper's bearing (machado2014, their model of an SKF 6208) with its
    # Table 1 values and the deck's former defaults.
    d, md = r.run("default", tend=0.0001)
    want = {"bearing": "machado2014", "catalog_name": "machado2014", "nb": 13, "db": 0.0126, "dext": 0.0732, "dinn": 0.048,
            "rc_ext": 0.00665, "rc_inn": 0.00655, "F": 320, "ring_mass": 0.15,
            "cage_mass": 0.008, "cage_clearance": 1e-4, "ring_damping": 6000}
    bad = {k: md.get(k) for k, v in want.items() if md.get(k) != v}
    check(not bad, f"default run: the paper's bearing machado2014, F = 320 N, ring 0.15 kg and 6000 N s/m, "
          f"cage 8 g, 0.1 mm play (differences: {bad})")


def deck_env():
    """The environment of a user who set nothing: no OHMDEM_CATALOG."""
    env = dict(os.environ)
    env.pop("OHMDEM_CATALOG", None)
    return env


def test_places(r):
    # The deck finds its catalog by itself (relative to the executable: the build's source
    # tree) from its own folder, as LIGGGHTS users run example decks, from the repository root
    # and from anywhere else, with no -var catalog and no OHMDEM_CATALOG: the same run each time.
    deck_dir = os.path.join(r.src, "inputs", "bearing_6208")
    elsewhere = os.path.join(r.workdir, "elsewhere")
    os.makedirs(elsewhere)
    places = [("own folder", deck_dir, "in.bearing"),
              ("repository root", r.src, os.path.join("inputs", "bearing_6208", "in.bearing")),
              ("another folder", elsewhere, os.path.join(deck_dir, "in.bearing"))]
    outputs = []
    for what, cwd, deck in places:
        out = os.path.join(r.workdir, "places_" + str(len(outputs)))
        res = subprocess.run([r.exe, "-in", deck, "-log", "none", "-var", "out", out, "-var", "tend",
                              "0.0005", "-var", "nout", "10"],
                             cwd=cwd, env=deck_env(), capture_output=True, text=True)
        ok = res.returncode == 0 and os.path.exists(os.path.join(out, "run.json"))
        check(ok, f"{what}: ohmdem -in {deck} ran (exit {res.returncode})"
              + ("" if ok else "\n" + res.stdout[-2000:] + res.stderr[-2000:]))
        if ok:
            outputs.append(out)
    if len(outputs) != len(places):
        return
    meta = json.load(open(os.path.join(outputs[0], "run.json")))
    check(meta["bearing"] == "machado2014" and meta["nb"] == 13, f"the default bearing ran: "
          f"{meta['bearing']} with {meta['nb']} balls")
    same = all(open(os.path.join(o, f), "rb").read() == open(os.path.join(outputs[0], f),
                                                             "rb").read()
               for o in outputs[1:] for f in ("signal.txt", "run.json"))
    check(same, "signal.txt and run.json identical from the three places")


def test_injection(r):
    # A bearing name never reaches a shell: names a shell would run are refused by name (the
    # message lists the known names) and create nothing, wherever the shell would have.
    cwd = os.path.join(r.workdir, "cwd")
    os.makedirs(cwd)
    markers = ["INJECTED", "X", "Y"]
    names = ["6208;touch INJECTED", "$(touch X)", "`touch Y`", "6208 && touch INJECTED",
             "6208|touch X", "../bearings/6208"]
    for name in names:
        out = os.path.join(r.workdir, "inj")
        res = subprocess.run([r.exe, "-in", r.deck, "-log", "none", "-var", "out", out,
                              "-var", "tend", "1e-5", "-var", "bearing", name],
                             cwd=cwd, env=deck_env(), capture_output=True)
        text = (res.stdout + res.stderr).decode(errors="replace")
        refused = (res.returncode != 0 and f"ERROR: bearing '{name}' is not a catalog name" in text
                   and "Known bearings in " in text and "6208" in text)
        check(refused, f"-var bearing {name!r} refused by name (exit {res.returncode})"
              + ("" if refused else "\n" + text[-1500:]))
    places = [cwd, r.workdir, os.path.join(r.workdir, "inj"), r.src,
              os.path.join(r.src, "inputs", "bearing_6208"), os.path.join(r.src, "inputs", "bearings")]
    made = [os.path.join(p, m) for p in places for m in markers
            if os.path.exists(os.path.join(p, m))]
    check(not made, f"no file created by the names ({made or 'none'})")


# The published kinematic orders of the sourced bearings simulated below (multiples of fr):
# MFPT's NiceBearing.m (E. Bechhoefer 2009; ../shared/data/bearing-real-mfpt/README.md) gives
# BPFI 4.75502; for the Paderborn 6203s (the KAt fact sheets: 8 balls of 6.75 mm on 29.05 mm,
# IBU/MTK, and on 28.55 mm, FAG) Harris' formula gives Z/2 (1 + Dw/Dpw) = 4 (1 + 6.75/29.05) =
# 4.92943 and 4 (1 + 6.75/28.55) = 4.94571.
SOURCED_BPFI = {"MFPT_NICE": 4.75502, "6203_IBU-MTK": 4.929432, "6203_FAG": 4.945709}


def test_sourced(r):
    # An inner-race pit on the sourced bearings of two other rigs passes the balls at their
    # BPFI. MFPT's shaft ran at 25 Hz, Paderborn's at 1500 rpm (also 25 Hz). Their balls weigh
    # 0.4-0.6 of the CWRU 6205's: dt 3e-6 s (CWRU's 5e-6 s scaled by about Db^1.25; a choice).
    omega = 25 * 2 * math.pi
    for name, bpfi in SOURCED_BPFI.items():
        out, meta = r.run(f"sourced_{name}", bearing=name, omega=repr(omega), dt=3e-6, tend=0.16,
                          defect="inner", size=1.0)
        check(meta["bearing"] == name and meta["catalog_name"] == name,
              f"{name}: run.json bearing {meta['bearing']!r}, catalog_name {meta['catalog_name']!r}")
        sig = read_signal(out)
        t_roll = rolling_from(sig, meta)
        check(t_roll is not None and t_roll < 0.04, f"{name}: rolling from t = {t_roll} s")
        if t_roll is None:
            continue
        f, n = pulse_rate(sig, t_roll + 0.005)
        ref = bpfi * 25
        check(f is not None and abs(f / ref - 1) < 5e-3,
              f"{name}: BPFI from {n} defect passes {f:.4f} Hz = {f / 25:.5f} fr vs "
              f"{bpfi} fr ({f / ref - 1:+.3%})")
    # A name several makers use runs its default entry, and run.json says which.
    out, meta = r.run("alias_6203", bearing="6203", tend=1e-4, dt=3e-6)
    check(meta["bearing"] == "6203-2RS_JEM" and meta["catalog_name"] == "6203",
          f"-var bearing 6203: run.json bearing {meta['bearing']!r}, catalog_name "
          f"{meta['catalog_name']!r}")
    # -var Dpw completes an entry that lacks the pitch diameter; the run is then custom.
    out, meta = r.run("kg_dpw", bearing="6204_KG", Dpw=0.0335, tend=1e-4, dt=3e-6)
    check(meta["bearing"] == "custom" and abs(meta["dp"] - 0.0335) < 1e-12
          and abs(meta["dext"] - 0.0411) < 1e-12,
          f"6204_KG with -var Dpw 0.0335: {meta['bearing']}, dp {meta['dp']}, dext {meta['dext']}")
    # Entries without what the simulation needs are refused, naming it and how to give it.
    for name, want in (("6204_KG", "-var Dpw M (pitch diameter"),
                       ("6201_NTN", "-var Nb N (number of balls; its factors give BPFO + BPFI = 7)"),
                       ("6208", "has no sourced geometry in the catalog: use machado2014 or 6208_KG")):
        res = subprocess.run([r.exe, "-in", r.deck, "-log", "none", "-var", "out",
                              os.path.join(r.workdir, "refused"), "-var", "tend", "1e-5",
                              "-var", "bearing", name], cwd=r.workdir, env=deck_env(),
                             capture_output=True)
        # bytes: an aborting MPI may write a partial line
        text = (res.stdout + res.stderr).decode(errors="replace")
        check(res.returncode != 0 and f"ERROR: bearing '{name}'" in text and want in text,
              f"-var bearing {name} refused naming {want!r}" + ("" if want in text else
                                                                 "\n" + text[-1500:]))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test")
    p.add_argument("--exe", required=True)
    p.add_argument("--post", required=True)
    p.add_argument("--src", required=True)
    a = p.parse_args()
    keep = os.environ.get("OHMDEM_KEEP_TEST_DIR")
    with tempfile.TemporaryDirectory(prefix=f"ohmdem_catalog_{a.test}_", dir=keep) as wd:
        r = Runner(os.path.abspath(a.exe), os.path.abspath(a.src), wd)
        {
            "kinematics": lambda: test_kinematics(r, os.path.abspath(a.post),
                                                  os.path.abspath(a.src)),
            "radial": lambda: test_radial(r),
            "resistance": lambda: test_resistance(r),
            "custom": lambda: test_custom(r),
            "places": lambda: test_places(r),
            "injection": lambda: test_injection(r),
            "sourced": lambda: test_sourced(r),
        }[a.test]()
    finish()


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Records made as a new user makes them: the deck under `load radial` with its defaults, the
R acquired through 0.1 A, 16 bits, 1 uV/sqrt(Hz) (the chain's white noise) and a low-pass at
0.4 of the rate, run.json beside the record with the defect's kind, size and place removed,
then plain `diagnose RECORD`. An inner pit must read `inner` (before: `unidentified`, the shaft
comb searched 2 % wide locked onto BPFI / 8 and masked the pit's comb); a healthy bearing must
name no family (before: `outer`, the start-up transient's drift taken for pulses). The speed
used must be run.json's within 0.2 %, and the output must say so.

    radial_defaults.py --exe OHMDEM --post OHMDEM_POST --deck DIR --work DIR --case inner|healthy
                       [--rate HZ] [-var NAME VALUE ...]
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys

ap = argparse.ArgumentParser()
ap.add_argument("--exe", required=True)
ap.add_argument("--post", required=True)
ap.add_argument("--deck", required=True)
ap.add_argument("--work", required=True)
ap.add_argument("--case", choices=["inner", "healthy"], required=True)
ap.add_argument("--rate", type=int, default=20000)
ap.add_argument("-var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
a = ap.parse_args()

shutil.rmtree(a.work, ignore_errors=True)
os.makedirs(a.work)
run = os.path.join(a.work, "run")
extra = [w for v in a.var for w in ("-var", *v)]
if a.case == "inner":
    extra = ["-var", "defect", "inner", "-var", "size", "1"] + extra
cmd = [a.exe, "-in", os.path.join(a.deck, "in.bearing"), "-var", "here", a.deck, "-var", "load",
       "radial", "-var", "tend", "0.2", "-var", "out", run, "-var", "nthermo", "100000", *extra]
with open(os.path.join(a.work, "log.txt"), "w") as log:
    subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, check=True)
rec = os.path.join(a.work, "record")
os.makedirs(rec)
meta = json.load(open(os.path.join(run, "run.json")))
stated_hz = meta["omega_inner"] / (2 * math.pi)
for key in ("defect", "size_deg", "depth", "position"):
    meta.pop(key, None)
json.dump(meta, open(os.path.join(rec, "run.json"), "w"))
u = os.path.join(rec, "U.txt")
subprocess.run([a.post, "acquire", os.path.join(run, "signal.txt"), "--scale", "0.1",
                "--lowpass", str(0.4 * a.rate), "--rate", str(a.rate), "--bits", "16", "--range",
                "0", "0.2", "--noise-density", "1e-6", "--name", "U", "--unit", "V", "--output",
                u], check=True, capture_output=True)
out = subprocess.run([a.post, "diagnose", u, "--no-size", "--format", "json"], check=True,
                     capture_output=True, text=True)
j = json.loads(out.stdout)
fams = {k: round(v["score"], 2) for k, v in j["families"].items()}
print(f"{'inner pit' if a.case == 'inner' else 'healthy bearing'} under load radial, {a.rate} Hz: {j['defect']} (candidate "
      f"{j.get('candidate')}), families {fams}, speed used {j['shaft_hz']:.6f} Hz "
      f"(stated {j['shaft_hz_stated']:.6f} Hz from {j['shaft_hz_stated_source']})")
ok = True
if a.case == "inner" and j["defect"] != "inner":
    print("FAILED: an inner pit under a radial load must read inner")
    ok = False
if a.case == "healthy" and j["defect"] in ("inner", "outer", "ball", "cage"):
    print("FAILED: a healthy bearing must name no family")
    ok = False
if abs(j["shaft_hz"] / stated_hz - 1) > 0.002 or abs(j["shaft_hz_stated"] / stated_hz - 1) > 1e-9:
    print("FAILED: the speed used must be run.json's within 0.2 %")
    ok = False
if not j["shaft_hz_stated_source"].endswith("run.json"):
    print("FAILED: the stated speed's source must be run.json")
    ok = False
text = subprocess.run([a.post, "diagnose", u, "--no-size"], check=True, capture_output=True,
                      text=True).stdout
if "# shaft frequency used (Hz):" not in text:
    print("FAILED: the text output must say which speed it used")
    ok = False
sys.exit(0 if ok else 1)

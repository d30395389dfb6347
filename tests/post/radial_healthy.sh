#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# A healthy 6208 under a radial load, its R acquired as a 20 kHz instrument
# records it (10 mA, 8 kHz anti-alias filter, 20 nV/sqrt(Hz)), must not read as a race defect:
# its R varies smoothly at BPFO as the balls pass the load zone (kurtosis 2.0 at the default
# speed and load, 2.71 at 300 rad/s and 640 N), no pulse train.
# Before: `outer`, score 1. Usage: radial_healthy.sh OHMDEM OHMDEM_POST DECK_DIR WORK_DIR
# [-var NAME VALUE ...] (another speed or load: the deck's variables, e.g. -var omega 300)
set -eu
ohmdem=$1 post=$2 deck=$3 work=$4
shift 4
rm -rf "$work" && mkdir -p "$work"
"$ohmdem" -in "$deck/in.bearing" -var here "$deck" -var load radial -var tend 0.215 \
  -var out "$work/run" -var nthermo 100000 "$@" > "$work/log.txt" 2>&1
"$post" acquire "$work/run/signal.txt" --scale 0.01 --lowpass 8000 --rate 20000 \
  --noise-density 2e-8 --output "$work/u20k.txt"
# from 0.05 s: the radially free ring has settled (its transient lasts to about 0.04 s)
"$post" diagnose "$work/u20k.txt" --metadata "$work/run/run.json" --from 0.05 --no-size \
  --format json > "$work/diagnosis.json"
/usr/bin/python3 - "$work/diagnosis.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
print("healthy radial 6208 at 20 kHz, omega", j["shaft_hz"] * 6.283185307179586, "rad/s:", j["defect"], "candidate", j.get("candidate"), "-", j.get("reason"))
assert j["defect"] == "none", j["defect"]
assert j.get("candidate") == "outer" and "smooth modulation at BPFO" in j["reason"], j
PY

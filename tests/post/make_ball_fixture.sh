#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Regenerates tests/post/data/ball_sim/acc12k.txt: the simulator's own ball defect (the paper's
# 6208, a 2-degree pit on ball 1, radial load 320 N, 500 rad/s, 0.315 s) through its vibration
# channel, the outer ring's acceleration along the load (acc_along, m/s^2), as a 12 kHz
# accelerometer records it (5 kHz anti-alias low-pass, no noise: the test adds it), from 0.05 s
# (the radially free ring has settled). Post tests read the file and never run the engine.
# Usage: make_ball_fixture.sh OHMDEM OHMDEM_POST REPO_DIR WORK_DIR
set -eu
ohmdem=$1 post=$2 repo=$3 work=$4
deck=$repo/inputs/bearing_6208
rm -rf "$work" && mkdir -p "$work"
"$ohmdem" -in "$deck/in.bearing" -var here "$deck" -var load radial -var defect ball \
  -var size 2.0 -var tend 0.315 -var out "$work/run" -var nthermo 100000 > "$work/log.txt" 2>&1
"$post" acquire "$work/run/signal.txt" --column acc_along --lowpass 5000 --rate 12000 \
  --output "$work/acc12k.txt"
mkdir -p "$repo/tests/post/data/ball_sim"
/usr/bin/python3 - "$work/acc12k.txt" "$repo/tests/post/data/ball_sim/acc12k.txt" <<'PY'
import sys
src, dst = sys.argv[1:]
with open(dst, "w") as out:
    out.write("# the simulator's ball defect, acc_along at 12 kHz (tests/post/make_ball_fixture.sh):\n"
              "# 6208 (machado2014), radial 320 N, 500 rad/s, 2-degree pit on ball 1 (m/s^2)\n"
              "# time acc_along\n")
    for line in open(src):
        if line.startswith("#"):
            continue
        t, v = map(float, line.split())
        if t >= 0.05:
            out.write(f"{t:.7g} {v:.6g}\n")
PY

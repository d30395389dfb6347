#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The 4-case partition sweep on 2 processes against the same 4 cases one after another (one
# partition, one process), in one run: wall times and their ratio (goal: at most 0.6).
#   bench/sweep/run_sweep_bench.sh [TEND]      (default 0.05 s simulated per case)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
eval "$(/usr/bin/python3 "$ROOT/studies/common.py" --shell)"  # OHMDEM, POST, OHMDEM_DECKS, ...
TEND=${1:-0.05}
DECK=$OHMDEM_DECKS
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
args=(-in "$DECK/in.sweep" -var here "$DECK" -var bearing_deck "$DECK/in.bearing" -var tend "$TEND")
cd "$WORK"
t0=$(date +%s.%N)
"$OHMDEM" "${args[@]}" -var root "$WORK/serial" -log none -screen none > /dev/null
t1=$(date +%s.%N)
mpirun --oversubscribe -np 2 "$OHMDEM" -partition 2x1 "${args[@]}" -var root "$WORK/parallel" \
  -log none > /dev/null
t2=$(date +%s.%N)
/usr/bin/python3 - "$t0" "$t1" "$t2" "$TEND" <<'PY'
import sys
t0, t1, t2, tend = map(float, sys.argv[1:])
s, p = t1 - t0, t2 - t1
print(f"4 cases of {tend} s simulated: one after another {s:.2f} s, 2-partition sweep on 2 processes "
      f"{p:.2f} s, ratio {p / s:.2f} (goal <= 0.6)")
PY

#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Cost of the electrical compute on the SKF 6208 scene, as ratios measured in one run:
# the mechanics alone, then R evaluated at every step (fix ave/time) in each mode, with the
# value of R each mode gives (greenwood against the exact Hertz areas: speed against error).
# Two measures: wall time (the fastest of ROUNDS interleaved runs per mode: a shared machine
# only ever slows a run down, and interleaving spreads its load over all modes alike), and,
# if valgrind is installed, instructions executed in the time loop (callgrind, noise-free).
#   bench/resistance/run_resistance_bench.sh [STEPS] [ROUNDS]   (default 30000 = 30 ms, 5)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
eval "$(/usr/bin/python3 "$ROOT/studies/common.py" --shell)"  # OHMDEM, POST, OHMDEM_DECKS, ...
STEPS=${1:-30000}
ROUNDS=${2:-5}
TEND=$(/usr/bin/python3 -c "print($STEPS*1e-6)")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

MODES=(mechanics greenwood exact greenwood_general holm)
declare -A ARGS=(
  [mechanics]="-var Revery 0"
  [greenwood]="-var Revery 1 -var area greenwood"
  [exact]="-var Revery 1 -var area exact"
  [greenwood_general]="-var Revery 1 -var area greenwood -var closedform no"
  [holm]="-var Revery 1 -var emodel holm"
)

# run NAME TEND [PREFIX...]: one run of the deck in mode NAME.
run() {
  local name=$1 tend=$2; shift 2
  # shellcheck disable=SC2086
  "$@" "$OHMDEM" -in "$OHMDEM_DECKS/in.bearing" -var out "$WORK/$name" \
    -var tend "$tend" -var nout 1000 -log "$WORK/$name.log" -screen none ${ARGS[$name]}
}

for ((k = 1; k <= ROUNDS; k++)); do
  for m in "${MODES[@]}"; do
    run "$m" "$TEND"
    awk -v m="$m" '/^Loop time of/ {print m, $4}' "$WORK/$m.log" >> "$WORK/times.txt"
  done
done
for m in "${MODES[@]}"; do
  r=$(awk 'NR == 1 {for (i = 2; i <= NF; i++) if ($i == "R") c = i - 1} END {print $c}' \
      "$WORK/$m/signal.txt")
  echo "$m $r" >> "$WORK/R.txt"
done

# Instructions in Verlet::run over 2000 steps (plus setup), per mode.
if command -v valgrind > /dev/null; then
  for m in "${MODES[@]}"; do
    run "$m" 0.002 valgrind --tool=callgrind --callgrind-out-file="$WORK/cg.$m" \
      --toggle-collect='LAMMPS_NS::Verlet::run(int)' > /dev/null 2>&1
    echo "$m $(awk '/^summary:|^totals:/ {print $2; exit}' "$WORK/cg.$m")" >> "$WORK/ir.txt"
  done
fi

/usr/bin/python3 - "$WORK" "$STEPS" "$ROUNDS" <<'PY'
import os, sys
work, steps, rounds = sys.argv[1], int(sys.argv[2]), sys.argv[3]
t = {}
for l in open(os.path.join(work, "times.txt")):
    m, s = l.split()
    t[m] = min(t.get(m, 1e9), float(s) / steps)
R = {l.split()[0]: float(l.split()[1]) for l in open(os.path.join(work, "R.txt"))}
ir = {}
if os.path.exists(os.path.join(work, "ir.txt")):
    ir = {l.split()[0]: float(l.split()[1]) for l in open(os.path.join(work, "ir.txt"))
          if len(l.split()) == 2}
mech = t["mechanics"]
print(f"SKF 6208, {steps} steps, one core: electrical compute at every step "
      f"(wall: fastest of {rounds} interleaved runs; instructions: callgrind, 2000 steps)")
print(f"{'mode':<20} {'s/step':>10} {'R cost / mechanics':>19} {'in instructions':>16} "
      f"{'R (ohm)':>12} {'R vs exact':>11}")
print(f"{'mechanics only':<20} {mech:>10.3e} {'-':>19} {'-':>16} {'-':>12} {'-':>11}")
for name in ("greenwood", "exact", "greenwood_general", "holm"):
    cost_ir = f"{(ir[name] - ir['mechanics']) / ir['mechanics']:.1%}" if name in ir and "mechanics" in ir else "-"
    err = f"{R[name] / R['exact'] - 1:+.2%}" if name != "holm" else "(model)"
    print(f"{name:<20} {t[name]:>10.3e} {(t[name] - mech) / mech:>19.1%} {cost_ir:>16} "
          f"{R[name]:>12.6g} {err:>11}")
PY

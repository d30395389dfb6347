#!/bin/bash
# Cost of the electrical compute on the SKF 6208 scene, as ratios measured in one run:
# the mechanics alone, then R evaluated at every step (fix ave/time) in each mode, with the
# value of R each mode gives (greenwood against the exact Hertz areas: speed against error).
#   bench/resistance/run_resistance_bench.sh [STEPS]      (default 30000 = 30 ms simulated)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
OHMDEM=${OHMDEM:-$ROOT/build/ohmdem}
STEPS=${1:-30000}
TEND=$(/usr/bin/python3 -c "print($STEPS*1e-6)")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# run NAME [-var ...]: prints "NAME seconds_per_step R"; the fastest of 3 runs (a shared
# machine only ever slows a run down).
run() {
  local name=$1; shift
  local t=1e9 k tk
  for k in 1 2 3; do
    "$OHMDEM" -in "$ROOT/inputs/bearing_6208/in.bearing" -var out "$WORK/$name" -var tend "$TEND" \
      -var nout 1000 -log "$WORK/$name.log" -screen none "$@"
    tk=$(awk '/^Loop time of/ {print $4}' "$WORK/$name.log")
    t=$(/usr/bin/python3 -c "print(min($t, $tk))")
  done
  local r
  r=$(awk 'NR == 1 {for (i = 2; i <= NF; i++) if ($i == "R") c = i - 1} END {print $c}' \
      "$WORK/$name/signal.txt")
  echo "$name $(/usr/bin/python3 -c "print($t/$STEPS)") $r"
}

{
  run mechanics -var Revery 0
  run greenwood -var Revery 1 -var area greenwood
  run exact -var Revery 1 -var area exact
  run greenwood_general -var Revery 1 -var area greenwood -var closedform no
  run holm -var Revery 1 -var emodel holm
} > "$WORK/results.txt"

/usr/bin/python3 - "$WORK/results.txt" "$STEPS" <<'PY'
import sys
rows = {l.split()[0]: (float(l.split()[1]), float(l.split()[2])) for l in open(sys.argv[1])}
mech = rows["mechanics"][0]
r_exact = rows["exact"][1]
print(f"SKF 6208, {sys.argv[2]} steps, one core: electrical compute at every step")
print(f"{'mode':<20} {'s/step':>10} {'R cost / mechanics':>19} {'R (ohm)':>12} {'R vs exact':>11}")
print(f"{'mechanics only':<20} {mech:>10.3e} {'-':>19} {'-':>12} {'-':>11}")
for name in ("greenwood", "exact", "greenwood_general", "holm"):
    t, r = rows[name]
    err = f"{r / r_exact - 1:+.2%}" if name != "holm" else "(model)"
    print(f"{name:<20} {t:>10.3e} {(t - mech) / mech:>19.1%} {r:>12.6g} {err:>11}")
PY

#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Cost of writing the signal at full rate on the SKF 6208 deck: the loop time (LIGGGHTS' "Loop
# time of", the time stepping alone) with signal.txt written every step against every 100th
# step (fix signal/table; R evaluated for every row written), every step in the binary .npy
# format (-var signal_format npy), and with fix print + equal-style variables writing the same
# columns every step in addition (-var printcheck 1). Interleaved runs, the fastest of REPS each.
# If valgrind is installed, also the instructions executed in the time loop (callgrind on
# 10000 steps: noise-free, but without the kernel's share of writing the file).
#   bench/signal/run_signal_bench.sh [TEND] [REPS]       (defaults: 0.2 s simulated, 3)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
eval "$(/usr/bin/python3 "$ROOT/studies/common.py" --shell)"  # OHMDEM, POST, OHMDEM_DECKS, ...
TEND=${1:-0.2}
REPS=${2:-3}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

loop_time() {  # loop_time NAME -var ...: prints the run's loop time (s)
  local name=$1; shift
  "$OHMDEM" -in "$OHMDEM_DECKS/in.bearing" -var out "$WORK/$name" -var tend "$TEND" \
    -log "$WORK/$name.log" -screen none "$@"
  sed -n 's/^Loop time of \([0-9.e+-]*\).*/\1/p' "$WORK/$name.log" | tail -1
}

every=(); hundredth=(); printed=(); binary=()
for ((k = 0; k < REPS; k++)); do
  every+=("$(loop_time every -var nout 1)")
  hundredth+=("$(loop_time hundredth -var nout 100)")
  binary+=("$(loop_time binary -var nout 1 -var signal_format npy)")
  printed+=("$(loop_time printed -var nout 1 -var printcheck 1)")
done
IR=""
if command -v valgrind > /dev/null; then
  for mode in "nout 100" "nout 1" "nout 1 npy"; do
    set -- $mode
    fmt=txt; [[ ${3:-} == npy ]] && fmt=npy
    valgrind --tool=callgrind --callgrind-out-file="$WORK/cg" --toggle-collect='LAMMPS_NS::Verlet::run(int)' \
      "$OHMDEM" -in "$OHMDEM_DECKS/in.bearing" -var out "$WORK/cg_$2$fmt" -var tend 0.01 \
      -var nout "$2" -var signal_format $fmt -log none -screen none > /dev/null 2>&1
    IR+="$(awk '/^summary:|^totals:/ {print $2; exit}' "$WORK/cg") "
  done
fi
/usr/bin/python3 - "$TEND" "${every[*]}" "${hundredth[*]}" "${printed[*]}" "${binary[*]}" "$IR" <<'PY'
import sys
tend = float(sys.argv[1])
a, b, c, d = (min(map(float, s.split())) for s in sys.argv[2:6])
steps = round(tend / 1e-6)
print(f"SKF 6208 deck, {tend} s simulated ({steps} steps), loop time, fastest of the runs")
print(f"  signal.txt every 100th step (fix signal/table): {b:.3f} s  {b / steps * 1e6:.2f} us/step")
print(f"  signal.txt every step       (fix signal/table): {a:.3f} s  {a / steps * 1e6:.2f} us/step"
      f"  ratio {a / b:.2f} (goal <= 1.5)")
print(f"  signal.npy every step       (format npy)      : {d:.3f} s  {d / steps * 1e6:.2f} us/step"
      f"  ratio {d / b:.2f} (goal <= 1.5)")
print(f"  + the same row through fix print every step   : {c:.3f} s  fix print alone adds "
      f"{(c - a) / steps * 1e6:.2f} us/row, {(c - a + b) / b:.2f}x the 100th-step run")
ir = sys.argv[6].split()
if len(ir) == 3:
    h, e, n = (int(x) / 10000 for x in ir)
    print(f"  instructions per step in the time loop (callgrind, 10000 steps): every 100th {h:.0f}, "
          f"every step text {e:.0f} (ratio {e / h:.2f}), npy {n:.0f} (ratio {n / h:.2f})")
PY

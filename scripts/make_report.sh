#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Regenerates the study report, REPORT_DIR/report.md, with its figures: the healthy and
# defective signals, the Fig. 13 / Fig. 15 counterparts, the validation numbers (from the test
# suite), the detectability and the load/speed studies, and the speed tables (ours vs stock
# LIGGGHTS, electrical cost, speed against error, partition sweep). The studies are the
# commands of studies/ (studies/README.md), the speed tables the benchmarks of bench/. Takes
# about 10 minutes on 2 cores (DETECTABILITY=--full: the whole detectability grid, longer).
#   scripts/make_report.sh [REPORT_DIR]          (default: report; needs a build in build/)
#   PARTS="load_speed detectability" scripts/make_report.sh doc/report   (only those, again)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=$(realpath -m "${1:-report}")
mkdir -p "$OUT"
WORK=$(mktemp -d)      # the runs' signals (hundreds of MB): only figures and tables are kept
trap 'rm -rf "$WORK"' EXIT
cd "$ROOT"
eval "$(/usr/bin/python3 studies/common.py --shell)"  # OHMDEM, POST, the MPI flags, ...

# PARTS: which parts to run again (the others keep their logs and figures in REPORT_DIR):
# any of defects load_speed detectability runup sizing validation speed signal; default all.
PARTS=" ${PARTS:-defects load_speed detectability runup sizing validation speed signal} "
want() { [[ "$PARTS" == *" $1 "* ]]; }

if want defects; then
  echo "== defect study (Fig. 13, Fig. 15)"
  /usr/bin/python3 studies/defects.py "$WORK/study" 0.12 > "$OUT/study.log"
  mkdir -p "$OUT/study"
  cp "$WORK"/study/*.png "$WORK"/study/*.csv "$WORK"/study/study.md "$OUT/study/"
fi
if want load_speed; then
  echo "== load and speed study"
  /usr/bin/python3 studies/load_speed.py "$WORK/load_speed" > "$OUT/load_speed.log"
  mkdir -p "$OUT/load_speed"
  cp "$WORK"/load_speed/*.png "$WORK"/load_speed/load_speed.csv "$WORK"/load_speed/load_speed.md \
     "$OUT/load_speed/"
fi
if want detectability; then
  echo "== detectability study (${DETECTABILITY:---quick} grid; DETECTABILITY=--full for the whole grid)"
  det_args=()
  [ "${DETECTABILITY:---quick}" = "--quick" ] && det_args=(--quick)
  /usr/bin/python3 studies/detectability.py "${det_args[@]}" "$WORK/detectability" \
    > "$OUT/detectability.log"
  mkdir -p "$OUT/detectability"
  cp "$WORK"/detectability/*.png "$WORK"/detectability/detectability.csv \
     "$WORK"/detectability/detectability.md "$OUT/detectability/"
  echo "== an inner pit's place from the accelerometer"
  /usr/bin/python3 studies/accel_position.py "$WORK/accel_position" > "$OUT/accel_position.log"
  cp "$WORK"/accel_position/accel_position.csv "$WORK"/accel_position/accel_position.md \
     "$OUT/detectability/"
  echo "== an inner pit's place from the electrical channel, the study's and held-out"
  # the same runs as the accelerometer's (OUT/sim), the held-out places and sizes in their own
  /usr/bin/python3 studies/accel_position.py --channel electrical "$WORK/accel_position" \
    > "$OUT/electrical_position.log"
  cp "$WORK"/accel_position/electrical_position.csv \
     "$WORK"/accel_position/electrical_position.md "$OUT/detectability/"
  heldout=0.4:40,0.4:190,0.4:275,0.5:70,0.5:130,0.5:215,0.5:345,0.7:100,0.7:230,0.7:320
  heldout=$heldout,1.2:40,1.2:190,1.2:275,1.5:70,1.5:130,1.5:215,1.5:345,1.8:100,1.8:230
  heldout=$heldout,1.8:320,2.2:40,2.2:190,2.2:275,2.5:70,2.5:130,2.5:215,2.5:345,2.6:100
  heldout=$heldout,2.6:230,2.6:320,2.8:40,2.8:190,2.8:275
  /usr/bin/python3 studies/accel_position.py --channel electrical --cases "$heldout" \
    "$WORK/electrical_heldout" > "$OUT/electrical_position_heldout.log"
  cp "$WORK"/electrical_heldout/electrical_position.csv \
     "$OUT/detectability/electrical_position_heldout.csv"
  sed '1s/$/: held-out places and sizes/' "$WORK"/electrical_heldout/electrical_position.md \
    > "$OUT/detectability/electrical_position_heldout.md"
  echo "== an outer pit's angle from a two-axis accelerometer"
  /usr/bin/python3 studies/accel_outer_angle.py "$WORK/accel_outer_angle" \
    > "$OUT/accel_outer_angle.log"
  cp "$WORK"/accel_outer_angle/accel_outer_angle.csv \
     "$WORK"/accel_outer_angle/accel_outer_angle.md "$OUT/detectability/"
fi
if want runup; then
  echo "== run-up study (order tracking)"
  /usr/bin/python3 studies/runup.py "$WORK/runup" > "$OUT/runup.log"
  mkdir -p "$OUT/runup"
  cp "$WORK"/runup/*.png "$WORK"/runup/orders.csv "$WORK"/runup/runup.md "$OUT/runup/"
fi
if want sizing; then
  echo "== sizing study (size and place from 10-50 kHz electrical records)"
  /usr/bin/python3 studies/sizing.py "$WORK/sizing" > "$OUT/sizing.log"
  mkdir -p "$OUT/sizing"
  cp "$WORK"/sizing/sizing.csv "$WORK"/sizing/sizing.md "$WORK"/sizing/curve_*.txt "$OUT/sizing/"
fi
if want validation; then
  echo "== validation numbers (test suite)"
  ctest --test-dir build -V -R "deck_hertz_static|deck_kinematics|deck_radial|deck_resistance|validation_|defect_frequencies|defect_sizes|defect_diagnose|vibration_" \
    > "$OUT/validation.log" 2>&1 || true
fi
if want speed; then
  echo "== speed: stock LIGGGHTS scenes, electrical cost, speed against error, sweep"
  bench/stock/run_stock.sh -n 30000 -o "$WORK/stock" > "$OUT/stock.log" 2>&1 || true
  bench/resistance/run_resistance_bench.sh 30000 > "$OUT/resistance.log"
  bench/speed_error/run_speed_error.sh "$WORK/speed_error" 0.1 > "$OUT/speed_error.log"
  mkdir -p "$OUT/speed_error"
  cp "$WORK"/speed_error/speed_error.png "$WORK"/speed_error/speed_error.csv "$OUT/speed_error/"
  bench/sweep/run_sweep_bench.sh 0.05 > "$OUT/sweep.log"
fi
if want signal; then
  echo "== signal writer: every step against every 100th"
  bench/signal/run_signal_bench.sh 0.2 3 > "$OUT/signal.log"
fi

# The report's date and version: the build's `ohmdem --version`, the source's commit and
# whether its tree had changes, today's date (a part kept from an earlier run keeps its log).
VERSION=$("$OHMDEM" --version | head -1 | cut -d" " -f1-2)
COMMIT=$(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo unknown)
git -C "$ROOT" diff --quiet HEAD 2>/dev/null || COMMIT="$COMMIT with local changes"
/usr/bin/python3 - "$OUT" "$VERSION" "$COMMIT" "$(date -u +%Y-%m-%d)" "$PARTS" <<'PY'
import os, re, sys
out, version, commit, date, parts = sys.argv[1:6]
def text(name):
    p = os.path.join(out, name)
    return open(p).read() if os.path.exists(p) else "(missing)"
checks = [re.sub(r"^\d+: ", "", l) for l in text("validation.log").splitlines()
          if re.match(r"^\d+: (ok  |FAIL|     )", l)]
study = text("study/study.md").replace("](", "](study/")
def section(name, folder):
    """A study's markdown inside the report: its title line dropped, its headings one level
    down, its figure links into its folder."""
    body = text(f"{folder}/{name}").replace("](", f"]({folder}/").split("\n")
    if body and body[0].startswith("# "):
        body = body[1:]
    return "\n".join("#" + l if l.startswith("## ") else l for l in body)
load_speed = section("load_speed.md", "load_speed")
detect = section("detectability.md", "detectability")
runup = section("runup.md", "runup")
stock = "\n".join(l for l in text("stock.log").splitlines()
                  if re.match(r"^(scene|primitive|mesh|ohmdem|SKF)", l))
report = f"""# ohmdem validation report

**{version}**, commit {commit}, {date}.

Regenerated by `scripts/make_report.sh` (parts run again: {", ".join(parts.split()) or "none"};
the others keep their earlier output). Machine: 2 cores shared; times are single runs. What
each part checks and how to rerun it: the studies' own commands (`studies/README.md`) and the
test names below.

## Signals and the defect study

{study}

## What an instrument would see: the detectability study

{detect}

## Loading conditions and speed

{load_speed}

## A run-up: order tracking

{runup}

## Validation (from the test suite: theory, closed forms, ngspice, kinematics)

```
{chr(10).join(checks)}
```

## Speed

Our bearing scene against stock LIGGGHTS on the same balls (`bench/stock/run_stock.sh`):

```
{stock}
```

Electrical compute at every step (`bench/resistance/run_resistance_bench.sh`):

```
{text("resistance.log").strip()}
```

Speed against error (`bench/speed_error/run_speed_error.sh`), R computed at every step:

```
{text("speed_error.log").strip()}
```

![error against cost](speed_error/speed_error.png)

Recommended time step per use (from the table above): dt = 1e-5 s (the largest stable step)
when only the defect frequencies matter (error 2e-5); the paper's 1e-6 s for the statistical
indicators, the paper's own reading (kurtosis within 0.6 %; at 5e-6 s it is off by 4 %); 5e-7 s
when the pulse shape matters (the size estimate, kurtosis within 0.2 %).

Writing the signal at full rate (`bench/signal/run_signal_bench.sh`):

```
{text("signal.log").strip()}
```

Partition sweep (`bench/sweep/run_sweep_bench.sh`):

```
{text("sweep.log").strip()}
```
"""
open(os.path.join(out, "report.md"), "w").write(report)
print(f"wrote {os.path.join(out, 'report.md')}")
PY

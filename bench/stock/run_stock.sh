#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Bearing benchmark runner: SKF 6208 balls between races, one run per scene, then a table of
# wall time per step and cage-speed error after the sliding phase (bench/README.md).
#
#   bench/stock/run_stock.sh [-n STEPS] [-o OUTDIR]
#
# STEPS: time steps per scene (dt = 1e-6 s; default 30000 = 30 ms: the stock scenes slide for
# 7-12 ms). OUTDIR (default ./bench_stock_out): one folder per scene (log, screen, cage.txt).
# Executables: $LIGGGHTS (default: liggghts on PATH), $OHMDEM (default: build/ohmdem).
# Adding a scene is one `scene` line in the scenes block below:
#   scene NAME EXECUTABLE DECK SERIES_FILE [-var ... arguments of the deck]
# Every scene also gets -var out OUTDIR/NAME and runs in that folder. SERIES_FILE (relative
# to it) needs a header naming columns 'time...' and 'omega_cage...' (cage_speed.py). Wall
# time per step: the deck's "bench: scene ... wall_s_per_step T" line if it prints one, else
# the sum of the log's "Loop time of T ... for N steps" lines. Exit status 1 if a scene failed.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
PY=/usr/bin/python3
eval "$($PY "$ROOT/studies/common.py" --shell)"  # OHMDEM, POST, OHMDEM_DECKS, ...
LIGGGHTS=${LIGGGHTS:-liggghts}
STEPS=30000
OUT=$PWD/bench_stock_out
while getopts "n:o:h" opt; do
  case $opt in
    n) STEPS=$OPTARG ;;
    o) OUT=$OPTARG ;;
    *) sed -n '2,15p' "$0"; exit 2 ;;
  esac
done
if ! [[ $STEPS =~ ^[1-9][0-9]*$ ]]; then
  echo "ERROR: -n expects a positive number of time steps, got '$STEPS'" >&2; exit 2
fi
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
DT=1e-6
TEND=$($PY -c "print($STEPS*$DT)")
# 2 pi FTF at 500 rad/s: 500/2 (1 - d/D), d and D from the catalog's 6208
THEORY=$($PY "$ROOT/studies/common.py" --cage-speed 500)
NB=$($PY "$ROOT/studies/common.py" --bearing nb)

# Race meshes for the stock mesh scenes (the catalog's 6208 races): bands 2 ball diameters high,
# faceting error <= 0.05 um
RIN=$($PY -c "print($($PY "$ROOT/studies/common.py" --bearing dinn) / 2)")
REXT=$($PY -c "print($($PY "$ROOT/studies/common.py" --bearing dext) / 2)")
BAND=$($PY -c "print(2 * $($PY "$ROOT/studies/common.py" --bearing db))")
MESHES=$OUT/meshes
if [ ! -s "$MESHES/inner.stl" ] || [ ! -s "$MESHES/outer.stl" ]; then
  mkdir -p "$MESHES"
  $PY "$HERE/make_ring_stl.py" --radius "$RIN" --height "$BAND" --max-error 5e-8 --normal out \
    --name inner -o "$MESHES/inner.stl"
  $PY "$HERE/make_ring_stl.py" --radius "$REXT" --height "$BAND" --max-error 5e-8 --normal in \
    --name outer -o "$MESHES/outer.stl"
fi

ROWS=()
FAILED=0
scene() {
  local name=$1 exe=$2 deck=$3 series=$4; shift 4
  local dir=$OUT/$name
  mkdir -p "$dir"
  echo "== $name: $exe -in $deck $* -var out $dir"
  local t0 rc=0
  t0=$(date +%s.%N)
  (cd "$dir" && "$exe" -in "$deck" "$@" -var out "$dir" -log "$dir/log.liggghts" \
      > "$dir/screen.txt" 2>&1) || rc=$?
  if [ $rc -ne 0 ]; then
    echo "   FAILED (exit $rc), last lines of $dir/screen.txt:"; tail -5 "$dir/screen.txt"
    ROWS+=("$name|-|-|failed")
    FAILED=$((FAILED + 1))
    return 0
  fi
  local timing
  timing=$(awk -v name="$name" '
      /^bench: scene / { for (i = 1; i < NF; i++) { if ($i == "steps") s = $(i+1);
                                                    if ($i == "wall_s_per_step") w = $(i+1) } }
      /^Loop time of / { lt += $4; ls += $9 }
      END { if (w != "") print s, w; else if (ls > 0) print ls, lt / ls; else print "- -" }' \
      "$dir/log.liggghts")
  local cage
  cage=$($PY "$HERE/cage_speed.py" "$dir/$series" --theory "$THEORY" || true)
  ROWS+=("$name|${timing% *}|${timing#* }|$cage")
  echo "   done in $($PY -c "import time; print('%.1f' % (time.time() - $t0))") s:" \
       "${timing#* } s/step; $cage"
}

# ---- scenes: NAME EXECUTABLE DECK SERIES_FILE deck arguments ------------------------------
scene primitive    "$LIGGGHTS" "$HERE/in.stock_primitive" cage.txt -var steps "$STEPS"
scene mesh_move    "$LIGGGHTS" "$HERE/in.stock_mesh" cage.txt -var steps "$STEPS" \
                   -var meshdir "$MESHES" -var motion move
scene mesh_surface "$LIGGGHTS" "$HERE/in.stock_mesh" cage.txt -var steps "$STEPS" \
                   -var meshdir "$MESHES" -var motion surface
scene ohmdem       "$OHMDEM" "$OHMDEM_DECKS/in.bearing" signal.txt -var tend "$TEND" -var nout 100

# ---- summary -----------------------------------------------------------------------------
echo
echo "SKF 6208, $NB balls, inner race 500 rad/s, dt = $DT s; cage speed theory 2 pi FTF =" \
     "$(printf %.4f "$THEORY") rad/s"
printf '%-14s %8s %12s %12s %11s %13s %10s\n' scene steps "wall s/step" \
       "x ${ROWS[0]%%|*}" "t_slide ms" "w_cage rad/s" "error %"
ref=""
for row in "${ROWS[@]}"; do
  IFS='|' read -r name steps sps cage <<< "$row"
  [ -z "$ref" ] && ref=$sps
  tsl=none wc=- err=-
  read -r _ tsl _ wc _ err _ <<< "$cage" || true
  $PY - "$name" "$steps" "$sps" "$ref" "$tsl" "$wc" "$err" <<'EOF2'
import sys
name, steps, sps, ref, tsl, wc, err = sys.argv[1:]
def num(s):
    try:
        return float(s)
    except ValueError:
        return None
settled = num(tsl) is not None
print('%-14s %8s %12s %12s %11s %13s %10s' % (
    name, steps,
    '%.3e' % num(sps) if num(sps) is not None else '-',
    '%.1f' % (num(sps) / num(ref)) if num(sps) is not None and num(ref) else '-',
    '%.1f' % (1e3 * num(tsl)) if settled else 'not settled',
    '%.4f' % num(wc) if num(wc) is not None else '-',
    ('%+.4f' % num(err)) if settled and num(err) is not None else '-'))
EOF2
done
if [ $FAILED -ne 0 ]; then
  echo "ERROR: $FAILED scene(s) failed" >&2
  exit 1
fi

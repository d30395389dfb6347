#!/bin/bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Speed against error on the SKF 6208 scene with a 1 deg inner-race defect: for each time step
# and mode, the wall time per simulated second (R computed at every step, signal.txt written at
# 100 kHz) next to the error of what users read against the finest run (dt = 2.5e-7 s): mean R,
# the identified defect frequency, the indicators (kurtosis, crest, RMS of R), the defect size
# estimate and the diagnosis; then the largest step that keeps each use within its tolerance.
# Prints a table, writes OUT/speed_error.csv and OUT/speed_error.png.
#   bench/speed_error/run_speed_error.sh [OUT] [TEND]        (defaults: speed-error, 0.1 s)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
eval "$(/usr/bin/python3 "$ROOT/studies/common.py" --shell)"  # OHMDEM, POST, OHMDEM_DECKS, ...
OUT=$(realpath -m "${1:-speed-error}")
TEND=${2:-0.1}
mkdir -p "$OUT"

# case NAME DT [-var ...]: one run; prints nothing, leaves OUT/NAME/{signal.txt,log,diag.json}
case_run() {
  local name=$1 dt=$2; shift 2
  local nout
  nout=$(/usr/bin/python3 -c "print(max(1, round(1e-5 / $dt)))")  # output at 100 kHz
  mkdir -p "$OUT/$name"
  "$OHMDEM" -in "$OHMDEM_DECKS/in.bearing" -var out "$OUT/$name" -var tend "$TEND" \
    -var dt "$dt" -var nout "$nout" -var Revery 1 -var defect inner -var size 1.0 \
    -log "$OUT/$name/log.liggghts" -screen none "$@"
  "$POST" diagnose --format json "$OUT/$name/signal.txt" > "$OUT/$name/diag.json"
  "$POST" stats --format json --from 0.015 "$OUT/$name/signal.txt" > "$OUT/$name/stats.json"
}

case_run ref_greenwood 2.5e-7
case_run ref_exact 2.5e-7 -var area exact
for dt in 5e-7 1e-6 2e-6 5e-6 1e-5; do
  case_run "greenwood_dt$dt" "$dt"
  case_run "exact_dt$dt" "$dt" -var area exact
done
case_run "general_dt1e-6" 1e-6 -var closedform no

/usr/bin/python3 - "$OUT" "$TEND" <<'PY'
import json, os, re, sys
import numpy as np
out, tend = sys.argv[1], float(sys.argv[2])
def load(name):
    path = os.path.join(out, name, "signal.txt")
    names = open(path).readline().lstrip("#").split()
    a = np.loadtxt(path)
    s = {n: a[:, i] for i, n in enumerate(names)}
    keep = s["time"] > 0.015
    log = open(os.path.join(out, name, "log.liggghts")).read()
    loop = sum(float(x) for x in re.findall(r"^Loop time of (\S+)", log, re.M))
    diag = json.load(open(os.path.join(out, name, "diag.json")))
    st = json.load(open(os.path.join(out, name, "stats.json")))
    size = diag.get("size") or {}
    return {"R": s["R"][keep].mean(), "wall": loop / tend, "f": diag["frequency_hz"] or float("nan"),
            "defect": diag["defect"], "kurtosis": st["kurtosis"], "crest": st["crest"],
            "rms": st["rms"], "size": size["size_deg"] if size.get("valid") else float("nan")}
ref = {m: load(f"ref_{m}") for m in ("greenwood", "exact")}
QUANT = ("R", "f", "kurtosis", "crest", "rms", "size")
def errors(r, m):
    return {q: abs(r[q] / ref[m][q] - 1) for q in QUANT}
rows = []
for m in ("greenwood", "exact"):
    for dt in ("5e-7", "1e-6", "2e-6", "5e-6", "1e-5"):
        r = load(f"{m}_dt{dt}")
        rows.append((m, dt, r["wall"], errors(r, m), r["defect"]))
g = load("general_dt1e-6")
rows.append(("greenwood, general solve", "1e-6", g["wall"], errors(g, "greenwood"), g["defect"]))
print(f"SKF 6208, 1 deg inner defect, {tend} s simulated, R at every step, output 100 kHz; reference dt = 2.5e-7 s")
print(f"reference (greenwood): mean R {ref['greenwood']['R']:.6f} ohm, f {ref['greenwood']['f']:.3f} Hz, "
      f"kurtosis {ref['greenwood']['kurtosis']:.3f}, crest {ref['greenwood']['crest']:.5f}, "
      f"size {ref['greenwood']['size']:.3f} deg, diagnosis {ref['greenwood']['defect']}")
hdr = (f"{'mode':<26} {'dt (s)':>7} {'wall s/sim s':>12} {'err R':>9} {'err f':>9} {'err kurt':>9} "
       f"{'err crest':>9} {'err RMS':>9} {'err size':>9}  diagnosis")
print(hdr)
csv = ["mode,dt_s,wall_s_per_sim_s,error_R,error_f,error_kurtosis,error_crest,error_rms,error_size,diagnosis"]
for m, dt, w, e, d in rows:
    print(f"{m:<26} {dt:>7} {w:>12.3f} " + " ".join(f"{e[q]:>9.2e}" for q in QUANT) + f"  {d}")
    csv.append(f"{m},{dt},{w:.6g}," + ",".join(f"{e[q]:.6g}" for q in QUANT) + f",{d}")
print(f"greenwood vs exact areas at the reference step: R differs by "
      f"{ref['greenwood']['R'] / ref['exact']['R'] - 1:+.2%} (model difference, not a numerical error)")
# The recommended step per use: the largest dt (greenwood) whose errors stay within the use's
# tolerance and whose diagnosis is still right.
USES = [("defect frequencies (spectrum, diagnosis)", {"f": 1e-3}),
        ("indicators (kurtosis, crest, RMS within 1 %)", {"kurtosis": 1e-2, "crest": 1e-2, "rms": 1e-2}),
        ("pulse shape (size estimate within 1 %, kurtosis within 0.5 %)", {"size": 1e-2, "kurtosis": 5e-3})]
print("recommended time step per use (largest dt within the tolerance, diagnosis inner):")
for use, tol in USES:
    ok = [float(dt) for m, dt, w, e, d in rows if m == "greenwood" and d == "inner"
          and all(e[q] <= t for q, t in tol.items())]
    best = f"{max(ok):g} s" if ok else "below 5e-7 s (none of the steps tried)"
    print(f"  {use:<62} {best}")
open(os.path.join(out, "speed_error.csv"), "w").write("\n".join(csv) + "\n")
dat = "\n".join(f"{w} " + " ".join(f"{max(e[q], 1e-16)}" for q in ("R", "f", "kurtosis"))
                 for m, dt, w, e, d in rows if m == "greenwood")
open(os.path.join(out, "speed_error_greenwood.dat"), "w").write(dat + "\n")
PY
gnuplot -e "set terminal pngcairo size 900,600; set output '$OUT/speed_error.png'; \
  set logscale xy; set xlabel 'wall time per simulated second (s)'; set ylabel 'relative error'; \
  set title 'SKF 6208, inner defect: error against cost (greenwood areas, dt from 5e-7 to 1e-5 s)'; \
  plot '$OUT/speed_error_greenwood.dat' using 1:2 with linespoints lw 2 title 'mean R', \
       '' using 1:3 with linespoints lw 2 title 'defect frequency', \
       '' using 1:4 with linespoints lw 2 title 'kurtosis'"
echo "wrote $OUT/speed_error.csv and $OUT/speed_error.png"

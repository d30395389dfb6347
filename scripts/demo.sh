#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The README's demo: installs what is missing, builds, runs the SKF 6208 scene healthy and with
# an inner-race defect (the deck's default ring load, force), post-processes both (indicators,
# spectra, diagnosis) and plots them. From a fresh clone the build takes most of its time.
#   scripts/demo.sh [OUTPUT_DIR]      (default: demo-output)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
# only what the demo runs (the tests are built by scripts/test.sh)
cmake --build build -j2 --target ohmdem ohmdem-post
out=$(realpath -m "${1:-demo-output}")
mkdir -p "$out"
post=build/ohmdem-post

run() {  # run NAME [-var ...]: 0.12 s of the paper's bearing (machado2014) at 500 rad/s, F = 320 N
  local name=$1; shift
  mkdir -p "$out/$name"
  echo "== $name: build/ohmdem -in inputs/bearing_6208/in.bearing -var tend 0.12 $*"
  build/ohmdem -in inputs/bearing_6208/in.bearing -var out "$out/$name" -var tend 0.12 "$@" \
    -log "$out/$name/log.liggghts" -screen none
  grep '^BEARING_SUMMARY' "$out/$name/log.liggghts"
}
run healthy
run inner_defect -var defect inner -var size 1.0

for name in healthy inner_defect; do
  sig="$out/$name/signal.txt"
  echo "== $name: indicators of R after the sliding phase"
  $post stats --from 0.015 "$sig" | grep -v '^#'
  echo "== $name: diagnosis (bearing and speed read from run.json)"
  $post diagnose "$sig" | grep -v '^#'
  $post plot --kind signal --from 0.03 --to 0.04 --output "$out/${name}_R.png" "$sig"
  # R as offsets from its mean (a healthy R varies by parts per million or less: no zoom)
  gnuplot -e "sig='$sig'; png='$out/${name}_dR.png'; name='$name'; t0=0.03; t1=0.04" \
    scripts/plot_offset.gp
  $post plot --kind spectrum --from 0.015 --logy --output "$out/${name}_spectrum.png" "$sig"
  $post plot --kind envelope --from 0.015 --output "$out/${name}_envelope.png" "$sig"
done
echo "note: inner_defect_spectrum.png also shows small peaks at odd multiples of BPFI/2 (313, 939,"
echo "  1565 Hz, about 40 dB under the BPFI lines). They are the time step's: BPFI's period is"
echo "  1600.5 steps of 1 us, so the pulse edges, which fall on steps, alternate between two"
echo "  widths every other pulse. With -var dt 5e-7 they sink to -66 dB (doc/deck_bearing.md)."
gnuplot -e "sig='$out/healthy/signal.txt'; png='$out/healthy_kinematics.png'; name='healthy'" \
  scripts/plot_kinematics.gp
echo "demo done: figures and signals in $out"
ls "$out"/*.png

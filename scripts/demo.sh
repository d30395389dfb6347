#!/usr/bin/env bash
# The README's demo: installs what is missing, builds, runs the SKF 6208 scene and plots it.
#   scripts/demo.sh [OUTPUT_DIR]      (default: demo-output)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
out=$(realpath -m "${1:-demo-output}")
mkdir -p "$out"

mkdir -p "$out/healthy"
echo "== healthy SKF 6208 at 500 rad/s, F = 320 N (0.05 s simulated)"
build/ohmdem -in inputs/bearing_6208/in.bearing -var out "$out/healthy" -var tend 0.05 \
  -var nout 10 -log "$out/healthy/log.liggghts" -screen none
grep '^BEARING_SUMMARY' "$out/healthy/log.liggghts"

echo "== plots"
gnuplot -e "sig='$out/healthy/signal.txt'; png='$out/healthy_kinematics.png'" scripts/plot_kinematics.gp
echo "demo done: $out/healthy/signal.txt, $out/healthy_kinematics.png"

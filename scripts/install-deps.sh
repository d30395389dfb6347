#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Installs the Debian packages ohmdem needs to build, test and run its demo, if missing.
set -euo pipefail
packages=(
  build-essential cmake pkg-config git
  liggghts libliggghts-dev liggghts-doc     # the engine we extend, its headers, its examples
  openmpi-bin libopenmpi-dev                # MPI (LIGGGHTS is built against Open MPI)
  libeigen3-dev libfftw3-dev libgtest-dev   # linear algebra, transforms, unit tests
  libhypre-dev                              # algebraic multigrid for large networks
  libboost-dev                              # Boost.Math: quantiles of detection thresholds
  ngspice                                   # independent circuit solver for network tests
  python3 python3-numpy python3-scipy       # independent references for signal statistics
  gnuplot-nox                               # plots (PNG through pngcairo)
  libmatio-dev                              # MATLAB .mat records (ohmdem-post --input mat)
  zlib1g-dev                                # compressed MAT variables checked whole
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi

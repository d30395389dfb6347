#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# The post-only build (-DOHMDEM_POST_ONLY=ON) for people who only analyse records: configures
# without LIGGGHTS, MPI, Eigen and hypre, builds ohmdem-post and its tests, runs them (label post).
#   post_only_build.sh SOURCE_DIR BUILD_DIR
set -eu
src=$1 build=$2
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DOHMDEM_POST_ONLY=ON >"$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; exit 1; }
# none of the engine's dependencies was looked for
if grep -E '^(LIGGGHTS_LIBRARY|HYPRE_LIBRARY|MPI_CXX_COMPILER|Eigen3_DIR):' "$build/CMakeCache.txt"; then
  echo "ERROR: the post-only configuration looked for an engine dependency"; exit 1
fi
cmake --build "$build" -j2 --target ohmdem-post post_tests
if ldd "$build/ohmdem-post" | grep -i -E 'liggghts|libmpi|hypre'; then
  echo "ERROR: ohmdem-post links an engine library"; exit 1
fi
[ ! -e "$build/ohmdem" ] || { echo "ERROR: the post-only build made the engine"; exit 1; }
ctest --test-dir "$build" -L post -j2 --output-on-failure

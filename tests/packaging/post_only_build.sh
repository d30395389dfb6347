#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# The post-only build (-DOHMDEM_POST_ONLY=ON) for people who only analyse records: configures
# without LIGGGHTS, MPI, Eigen and hypre, builds ohmdem-post and runs it on the test fixtures
# (a text table, a NumPy table, a MAT file, the catalog). The post tests themselves run in the
# main build on the same sources; building them a second time here would double the cost.
#   post_only_build.sh SOURCE_DIR BUILD_DIR
set -eu
src=$1 build=$2
# -O0: this checks the configuration, the link and a run, not the optimiser (half the compile time)
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O0 -DNDEBUG" \
  -DOHMDEM_POST_ONLY=ON >"$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; exit 1; }
# none of the engine's dependencies was looked for
if grep -E '^(LIGGGHTS_LIBRARY|HYPRE_LIBRARY|MPI_CXX_COMPILER|Eigen3_DIR):' "$build/CMakeCache.txt"; then
  echo "ERROR: the post-only configuration looked for an engine dependency"; exit 1
fi
cmake --build "$build" -j2 --target ohmdem-post
if ldd "$build/ohmdem-post" | grep -i -E 'liggghts|libmpi|hypre'; then
  echo "ERROR: ohmdem-post links an engine library"; exit 1
fi
[ ! -e "$build/ohmdem" ] || { echo "ERROR: the post-only build made the engine"; exit 1; }
post=$build/ohmdem-post data=$src/tests/post/data
"$post" stats "$data/print.txt" --column rke --time-column none --rate 1000 > "$build.stats.txt"
grep -q '^kurtosis' "$build.stats.txt" || { cat "$build.stats.txt"; exit 1; }
"$post" stats "$data/npy/table.npy" --column x | grep -q '^rms' || exit 1
"$post" stats "$data/mat/good.mat" --variable x --rate 1000 | grep -q '^rms' || exit 1
# the catalog, from the source tree: CWRU's published BPFI multiple of the 6205-2RS JEM
"$post" frequencies --bearing 6205-2RS_JEM --rpm 60 | grep -q '5.415' || exit 1
echo "post-only build: ohmdem-post built without the engine's libraries and ran"


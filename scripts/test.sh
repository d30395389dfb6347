#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Installs what is missing, builds ohmdem and ohmdem-post once, and runs the tests by cost tier
# (tests/README.md):
#   scripts/test.sh          the unit and integration tiers (the README's test command)
#   scripts/test.sh --full   also the validation tier (measured records, studies, the post-only
#                            build) and the sanitizer stage (what CI runs)
set -euo pipefail
cd "$(dirname "$0")/.."
full=0
case "${1:-}" in
  "") ;;
  --full) full=1 ;;
  *) echo "usage: scripts/test.sh [--full]" >&2; exit 2 ;;
esac
scripts/install-deps.sh
# Open MPI refuses to run as root unless told; CI runs as root. 2 cores: oversubscribe.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# A run started without mpirun (most deck tests) does not start Open MPI's orted daemon: 0.2 s
# less per run (0.35 s instead of 0.55 s for a 2-step deck), the same numbers; the runs under
# mpirun are not singletons and do not read it.
export OMPI_MCA_ess_singleton_isolated=1
launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi

# tiers BUILD LABELS: the tests of those tiers, then the ones that took longer than their tier
# allows (a report: the budget is the tier's promise to whoever runs it)
tiers() {
  local build=$1 labels=$2 status=0
  ctest --test-dir "$build" --output-on-failure -j2 -L "$labels" || status=$?
  cp "$build/Testing/Temporary/LastTest.log" "$build/last_tier_run.log"
  /usr/bin/python3 tests/packaging/check_tiers.py --times "$build/last_tier_run.log" "$build" || true
  return $status
}

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}"
cmake --build build -j2
tiers build 'unit|integration'
[ "$full" = 1 ] || exit 0

tiers build validation

# The post-processing and network kernels' tests again under AddressSanitizer + UBSan: bad input
# must give a clear error, never a memory error. The sanitizer build registers only the tests
# of what it instruments (tests/CMakeLists.txt: the engine links the uninstrumented libliggghts).
# -O1 -g1 (line tables): the sanitizers' reports keep file and line, and the files compile in
# half the time of -O2 -g.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOHMDEM_ASAN=ON "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
cmake --build build-asan -j2 --target test_programs
export ASAN_OPTIONS=detect_leaks=1
tiers build-asan 'unit|integration'

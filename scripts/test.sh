#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Installs what is missing, builds ohmdem and ohmdem-post, and runs the whole test suite.
#   scripts/test.sh            (the README's test command; CI runs it too)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# Open MPI refuses to run as root unless told; CI runs as root. 2 cores: oversubscribe.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# A run started without mpirun (most deck tests) does not start Open MPI's orted daemon: 0.2 s
# less per run (0.35 s instead of 0.55 s for a 2-step deck), the same numbers; the runs under
# mpirun are not singletons and do not read it.
export OMPI_MCA_ess_singleton_isolated=1
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
ctest --test-dir build --output-on-failure -j2 -LE build

# The post-only build (-DOHMDEM_POST_ONLY=ON: ohmdem-post without LIGGGHTS, MPI,
# hypre) in a build folder of its own: a step apart, as it compiles the post tool again.
ctest --test-dir build --output-on-failure -L build

# The post-processing and network kernels again under AddressSanitizer + UBSan: bad input
# must give a clear error, never a memory error (the engine itself links the uninstrumented
# libliggghts and is not built here).
# -O1 -g1 (line tables): the sanitizers' reports keep file and line, and the files compile in
# half the time of -O2 -g, the largest single cost of CI.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOHMDEM_ASAN=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
cmake --build build-asan -j2 --target ohmdem-post post_tests test_network test_conductance_laws test_electric \
  test_signal_table test_vtk_series
# Left out there: the tests that take 10 s or more under the sanitizers (numerical runs over
# whole records, real or synthetic: the same code paths as the faster tests, checked above in
# the Release build). post.RealData.DiagnoseEveryMeasuredRecordAndPrint stays: it takes every
# real record through the reader and diagnose under the sanitizers.
export ASAN_OPTIONS=detect_leaks=1
slow='Diagnose.NoiseSweepReportsTheSnrLimit:Diagnose.DefectSizeFromPulseWidths:Diagnose.HealthySignalsAreNone'
slow+=':RealData.OtherChannelKeepsDriveEndVerdictsAndClearsFanEndFlags:RealData.FanEndChannelsOfDriveEndFaultsNameTheOtherBearing'
slow+=':RealData.ShaftSpeedFromTheSpectrumOfMfptRecords:RealData.HealthyFanEndChannelsNameNoFamily'
slow+=':RealData.MainsCombsMaskedAsGiven:RealData.FanEndWithTheShared6203Name'
slow+=':Detect.MeasuredCwruRecords:Detect.MeasuredCwruAgainstAHealthyBaseline:Detect.CommandLineReportsDetection'
slow+=':CatalogSources.DiagnoseWithTheNiceEntryFindsTheFamilyOfEachMfptRecord'
slow+=':Cli.DiagnoseSizeIntervalAndPosition:Cli.DiagnoseOurRunFromItsMetadata:Collect.DiagnosisColumnsEqualDiagnose'
slow+=':DiagnoseDoubleImpulse.RealRecordsGiveASizeWithIntervalOrSayWhyNot'
# post_tests' cases in two processes (gtest's shards), not one process each through ctest: an
# instrumented post_tests takes ~0.5 s to start, which was two thirds of this stage's time.
(
  cd build-asan/tests/post
  for shard in 0 1; do
    GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=$shard ./post_tests --gtest_filter="-$slow" \
      > "../../post_tests_asan_$shard.log" 2>&1 &
  done
  failed=0
  for shard in 0 1; do wait -n || failed=1; done
  for shard in 0 1; do
    log=../../post_tests_asan_$shard.log
    tail -n 1 "$log"
    if [ "$failed" = 1 ]; then grep -E -B2 -A30 'FAILED|ERROR: (Address|Leak)Sanitizer|runtime error' "$log" | head -n 200 || true; fi
  done
  exit $failed
)
# The rest (the command-line runs of ohmdem-post, the network and signal kernels' tests).
ctest --test-dir build-asan --output-on-failure -j2 -L 'post|network|signal' \
  -E '^post\.([A-Z]|diagnose_benchmark$|diagnose_synthetic$)'

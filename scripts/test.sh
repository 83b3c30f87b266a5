#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Sets up, builds and runs the whole test suite: every test on the Release build; then, on a
# clang build with AddressSanitizer, UndefinedBehaviorSanitizer and the engine's invariant checks
# (PCL_WRAP_CHECK_INVARIANTS), the unit and end-to-end tests again and a bounded run of each
# fuzzer (PCL_WRAP_FUZZ_SECONDS, default 60). The Python package is not built there: an
# instrumented module does not load into Debian's uninstrumented python3.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs="$(nproc)"

scripts/build.sh
(cd build && ctest -j"$jobs" --output-on-failure)

CC=clang CXX=clang++ BUILD_DIR=build-sanitize scripts/build.sh -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPCL_WRAP_SANITIZE=address,undefined -DPCL_WRAP_BUILD_FUZZERS=ON -DPCL_WRAP_BUILD_BENCH=OFF -DPCL_WRAP_BUILD_ROS=OFF \
  -DPCL_WRAP_BUILD_PYTHON=OFF -DPCL_WRAP_CHECK_INVARIANTS=ON \
  -DPCL_WRAP_FUZZ_SECONDS="${PCL_WRAP_FUZZ_SECONDS:-60}"
# The real-data, installed-package, ROS and viewer tests add nothing a sanitizer would see but time;
# so do the tests whose point is size (a 1M cloud, five noisy 100k clouds, enough points for the
# progress display, a bunny and a torus at several thresholds under MPI), whose code the smaller
# tests run here too. The Release build above runs them all.
sized="LargeCloud\.|NoiseOfASpacingLeavesNoInnerVoidAndFewHandles|ProgressOnStderrWhenAskedOrOnATerminal|Mpi\.ThresholdsAreTheSingleProcesss"
(cd build-sanitize && ctest -j"$jobs" --output-on-failure -E "RealData|DownstreamConsumer|RosNode|Viewer|Package|$sized")

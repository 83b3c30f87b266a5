#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the project and runs the benchmark on spheres of 10k, 100k and 1M points (or the sizes
# given as arguments). Prints, per size, CGAL's triangulation times and pcl_wrap's stages, each
# the fastest of BENCH_RUNS (default 3) runs taken in turns.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(10000 100000 1000000)
for n in "${sizes[@]}"; do
  build/bench/bench_wrap sphere "$n" 1 "${BENCH_RUNS:-3}"
done

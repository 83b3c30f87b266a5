#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Sets up, builds, and wraps the Stanford bunny: writes out/bunny_wrap.ply (and the same surface
# as out/bunny_wrap.vtk, which pcl_viewer opens) and prints a summary.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
scripts/fetch-data.sh
mkdir -p out
build/apps/pcl_wrap data/fetched/bunny00.off out/bunny_wrap.ply --stats --stats-json out/bunny_wrap_stats.json
build/apps/pcl_wrap data/fetched/bunny00.off out/bunny_wrap.vtk --quiet
echo "wrote out/bunny_wrap.ply and out/bunny_wrap.vtk (view it with: pcl_viewer out/bunny_wrap.vtk)"

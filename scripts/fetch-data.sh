#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Extracts sample data from Debian's libcgal-demo package into data/fetched/:
# the Stanford bunny (a mesh whose vertices are a scan), the kitten scan, the fandisk CAD model, the
# cow and the man (a figure whose hands hang close to its body).
set -euo pipefail
cd "$(dirname "$0")/.."
archive=/usr/share/doc/libcgal-dev/data.tar.gz
[ -f "$archive" ] || { echo "fetch-data: $archive missing: run scripts/setup.sh" >&2; exit 1; }
mkdir -p data/fetched
for f in data/meshes/bunny00.off data/points_3/kitten.xyz data/meshes/fandisk.off data/meshes/cow.off \
  data/meshes/man.off; do
  [ -f "data/fetched/$(basename "$f")" ] || tar -xzf "$archive" -O "$f" > "data/fetched/$(basename "$f")"
done
# The bunny's points alone as a PLY file, for examples/python/wrap_bunny.py.
if [ ! -f data/fetched/bunny00_points.ply ]; then
  awk '/^[[:space:]]*(#|$)/ || (!header && $1 == "OFF") { next } # blank, comment, the OFF line
       !header { header = 1; n = $1; print "ply\nformat ascii 1.0\nelement vertex " n
                 print "property double x\nproperty double y\nproperty double z\nend_header"; next }
       written < n { print $1, $2, $3; ++written }' data/fetched/bunny00.off > data/fetched/bunny00_points.ply.part
  mv data/fetched/bunny00_points.ply.part data/fetched/bunny00_points.ply
fi

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Extracts sample data from Debian's libcgal-demo package into data/fetched/:
# the Stanford bunny (a mesh whose vertices are a scan), the kitten scan and the fandisk CAD model.
set -euo pipefail
cd "$(dirname "$0")/.."
archive=/usr/share/doc/libcgal-dev/data.tar.gz
[ -f "$archive" ] || { echo "fetch-data: $archive missing: run scripts/setup.sh" >&2; exit 1; }
mkdir -p data/fetched
for f in data/meshes/bunny00.off data/points_3/kitten.xyz data/meshes/fandisk.off; do
  [ -f "data/fetched/$(basename "$f")" ] || tar -xzf "$archive" -O "$f" > "data/fetched/$(basename "$f")"
done

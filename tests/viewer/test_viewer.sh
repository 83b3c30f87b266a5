#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: test_viewer.sh PCL_WRAP_CLI MESH_TO_VTK INPUT
#
# Under Xvfb: scripts/render.sh draws INPUT's cloud, raw W and default surface with pcl_viewer
# (each checked not blank); then the CLI's .vtk, .obj and .ply outputs open in pcl_viewer: .vtk as
# written, .obj through PCL's pcl_obj2vtk, .ply through PCL's PLY reader.
set -euo pipefail
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi
cli=$1 mesh_to_vtk=$2 input=$3
scripts=$(cd "$(dirname "$0")/../../scripts" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

PCL_WRAP_CLI=$cli "$scripts/render.sh" "$input" "$work/pictures"

for format in vtk obj ply; do
  "$cli" "$input" "$work/w.$format" --quiet
done
pcl_obj2vtk "$work/w.obj" "$work/w_obj.vtk" > /dev/null
"$mesh_to_vtk" "$work/w.ply" "$work/w_ply.vtk"
for vtk in w.vtk w_obj.vtk w_ply.vtk; do
  "$scripts/view.sh" "$work/$vtk" "$work/$vtk.png"
  python3 "$scripts/png_coverage.py" "$work/$vtk.png" 0.02
done

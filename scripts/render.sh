#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: scripts/render.sh INPUT OUT_DIR [pcl_wrap options for both surfaces]
#        (installed: pcl_wrap_render INPUT OUT_DIR [options])
#
# Pictures with PCL's pcl_viewer (under Xvfb when there is no display): the input cloud, the
# paper's W (--raw) and the default surface, as OUT_DIR/NAME_cloud.png, NAME_raw.png and
# NAME_surface.png. Fails if a picture is blank. Uses the tool named by PCL_WRAP_CLI, else
# build/apps/pcl_wrap in the source tree, else the installed pcl_wrap beside it.
set -euo pipefail
usage() { sed -n '3,9p' "$(readlink -f "$0")" | cut -c3-; }
case "${1:-}" in -h | --help) usage; exit 0 ;; esac
[ $# -ge 2 ] || { usage >&2; exit 2; }
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi
here=$(cd "$(dirname "$(readlink -f "$0")")" && pwd)
cli=${PCL_WRAP_CLI:-$here/../build/apps/pcl_wrap}
[ -x "$cli" ] || cli=$here/../../../bin/pcl_wrap # installed: <prefix>/share/pcl_wrap/scripts
input=$1 out=$2
shift 2
options=("$@")
name=$(basename "${input%.*}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

"$cli" "$input" "$work/raw.vtk" --quiet --raw "${options[@]}"
"$cli" "$input" "$work/surface.vtk" --quiet "${options[@]}"
# The cloud: the output's vertices are the input points; pcl_viewer draws float fields.
"$cli" "$input" "$work/points.obj" --quiet --raw
awk '/^v / { print $2, $3, $4 }' "$work/points.obj" > "$work/points.xyz"
pcl_xyz2pcd "$work/points.xyz" "$work/cloud.pcd" > /dev/null

for picture in cloud:cloud.pcd raw:raw.vtk surface:surface.vtk; do
  png="$out/${name}_${picture%%:*}.png"
  "$here/view.sh" "$work/${picture#*:}" "$png"
  python3 "$here/png_coverage.py" "$png" 0.02
done

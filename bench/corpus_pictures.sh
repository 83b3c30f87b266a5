#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: bench/corpus_pictures.sh CORPUS_DIR OUT_DIR CASE[:cut]...
#
# For each case of a corpus written by bench/corpus.py, one picture of three surfaces side by
# side: the paper's W (pcl_wrap --raw), the default surface, and CGAL's Advancing Front on the
# same points, each rendered by PCL's pcl_viewer (scripts/view.sh, under Xvfb when there is no
# display), as OUT_DIR/corpus_CASE.png. With ":cut", the surfaces' upper halves are left out to
# show what is inside (bench/cut_mesh.py). Uses build/apps/pcl_wrap and build/bench/bench_peers.
set -euo pipefail
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi
here=$(cd "$(dirname "$0")" && pwd)
build=${PCL_WRAP_BUILD:-$here/../build}
corpus=$1 out=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
for case in "$@"; do
  name=${case%:cut}
  cloud=$corpus/$name.xyz
  "$build/apps/pcl_wrap" "$cloud" "$work/raw.obj" --quiet --raw
  "$build/apps/pcl_wrap" "$cloud" "$work/default.obj" --quiet
  "$build/bench/bench_peers" cgal_advancing_front "$cloud" 0 1 --mesh "$work/front.obj" > /dev/null
  for surface in raw default front; do
    if [ "$case" != "$name" ]; then
      "$here/cut_mesh.py" "$work/$surface.obj" "$work/cut.obj"
      mv "$work/cut.obj" "$work/$surface.obj"
    fi
    pcl_obj2vtk "$work/$surface.obj" "$work/$surface.vtk" > /dev/null
    "$here/../scripts/view.sh" "$work/$surface.vtk" "$work/$surface.png"
  done
  "$here/side_by_side.py" "$out/corpus_$name.png" \
    "$work/raw.png:the paper's W" "$work/default.png:pcl_wrap" "$work/front.png:Advancing Front"
done

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: scripts/view.sh FILE OUT.png
#
# Opens FILE (.pcd or .vtk) in PCL's pcl_viewer on the current X display, resets the camera to
# fit it ('r'; points drawn 3 pixels wide) and saves pcl_viewer's own snapshot ('j') as OUT.png,
# without the bottom strip where pcl_viewer writes the file's name and the frame rate. Without a
# display, run it under xvfb-run: xvfb-run -a -s "-screen 0 1280x1024x24" scripts/view.sh FILE OUT.png
set -euo pipefail
file=$(realpath "$1") out=$(realpath -m "$2")
work=$(mktemp -d)
viewer=""
cleanup() {
  if [ -n "$viewer" ]; then
    kill "$viewer" 2> /dev/null || true
    wait "$viewer" 2> /dev/null || true # its window is gone before the next viewer is searched for
  fi
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work" # pcl_viewer writes its snapshot to the working directory
points=()
[[ "$file" != *.pcd ]] || points=(-ps 3) # points 3 pixels wide
pcl_viewer "$file" "${points[@]}" > viewer.log 2>&1 &
viewer=$!
window=$(timeout 60 xdotool search --sync --name "PCD viewer" | head -1) || {
  echo "view.sh: pcl_viewer opened no window for $1:" >&2
  tr '\r' '\n' < viewer.log >&2
  exit 1
}
sleep "${VIEW_WAIT:-3}" # let it load and draw
xdotool key --window "$window" r j
for _ in $(seq 100); do
  compgen -G "screenshot-*.png" > /dev/null && break
  sleep 0.1
done
sleep 0.5 # the snapshot is written, not only created
snapshot=$(compgen -G "screenshot-*.png" | head -1) || {
  echo "view.sh: pcl_viewer saved no snapshot of $1" >&2
  exit 1
}
if grep -qi "error\|failed" viewer.log; then
  echo "view.sh: pcl_viewer reported a problem with $1:" >&2
  tr '\r' '\n' < viewer.log >&2
  exit 1
fi
/usr/bin/python3 - "$snapshot" "$out" << 'EOF' # Debian's, with python3-pil
import sys
from PIL import Image
image = Image.open(sys.argv[1])
image.crop((0, 0, image.width, image.height - 28)).save(sys.argv[2])
EOF

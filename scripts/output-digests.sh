#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: scripts/output-digests.sh [BUILD_DIR]  (default build/)
#
# One line per case: the SHA-256 of every file pcl_wrap writes (the mesh as binary PLY and, for
# the smaller inputs, the --complex JSON) on the sample models and generated clouds of every kind
# the library meets: closed shapes, tunnels, noise, single layers, several objects, degenerate
# sets. A change that must not change behaviour leaves this list as it was: run it before and
# after, and compare.
#
#   scripts/output-digests.sh > before.txt; (change, rebuild); scripts/output-digests.sh | diff before.txt -
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$here/build}" && pwd)
cli=$build/apps/pcl_wrap
[ -x "$cli" ] || { echo "output-digests: $cli missing: run scripts/build.sh" >&2; exit 1; }
"$here/scripts/fetch-data.sh"
archive=/usr/share/doc/libcgal-dev/data.tar.gz
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The development models from libcgal-demo.
inputs=()
for f in meshes/bunny00.off points_3/kitten.xyz meshes/fandisk.off meshes/cow.off meshes/dino.off \
         meshes/lion.off meshes/bull.off meshes/triceratops.off meshes/knot1.off meshes/mushroom.off \
         meshes/man.off meshes/blobby.off meshes/cheese.off meshes/anchor_dense.off points_3/oni.ply \
         points_3/ball.ply points_3/half.xyz points_3/sphere_20k.xyz points_3/cube.xyz; do
  name=$(basename "$f")
  if tar -xzf "$archive" -O "data/$f" > "$work/$name" 2> /dev/null; then
    inputs+=("$work/$name")
  fi
done

# Generated clouds, fixed seeds.
/usr/bin/python3 - "$work" <<'PY'
import sys
import numpy as np
out = sys.argv[1]
rng = np.random.default_rng(7)
def save(name, p):
    np.savetxt(f"{out}/{name}.xyz", p, fmt="%.17g")
def sphere(n, r=1.0, c=(0, 0, 0), noise=0.0):
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1)[:, None]
    return np.asarray(c) + d * (r + noise * rng.normal(size=(n, 1)))
def torus(n, R=1.0, r=0.4, c=(0, 0, 0)):
    u, v = rng.uniform(0, 2 * np.pi, (2, n))
    return np.asarray(c) + np.c_[(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)]
save("sphere_noisy", sphere(8000, noise=5e-3))
save("torus", torus(6000))
save("two_spheres", np.r_[sphere(3000), sphere(3000, c=(3, 0, 0))])
save("sphere_and_torus", np.r_[sphere(3000), torus(4000, c=(3.5, 0, 0))])
save("hollow_ball", np.r_[sphere(4000), sphere(2000, r=0.5)])
x, y = rng.uniform(-1, 1, (2, 5000))
save("terrain", np.c_[x, y, 0.2 * np.sin(3 * x) * np.cos(2 * y)])
x, y = rng.uniform(-1, 1, (2, 5000))
save("terrain_rough", np.c_[x, y, 0.2 * np.sin(3 * x) * np.cos(2 * y) + 0.02 * rng.normal(size=5000)])
h = sphere(6000)
save("half_sphere", h[h[:, 2] > 0])
g = np.stack(np.meshgrid(*[np.arange(10)] * 3), -1).reshape(-1, 3).astype(float)
save("grid", g)
g = np.stack(np.meshgrid(np.arange(30), np.arange(30)), -1).reshape(-1, 2).astype(float)
save("plane_grid", np.c_[g, np.zeros(len(g))])
t = rng.uniform(0, 1, 500)
save("near_collinear", np.c_[t, 2 * t + 1e-12 * rng.normal(size=500), 3 * t])
save("outlier", np.r_[sphere(3000), [[1e6, 0, 0]]])
PY
inputs+=("$work"/*.xyz)

digest () { sha256sum "$1" | cut -c1-16; }
for input in "${inputs[@]}"; do
  name=$(basename "$input")
  [ -s "$input" ] || continue
  for options in "" "--raw" "--raw --manifold" "--threads 1"; do
    line="$name ${options:-default}:"
    if "$cli" "$input" "$work/out.ply" $options > /dev/null 2> "$work/err"; then
      line+=" $(digest "$work/out.ply")"
    else
      line+=" failed $(digest "$work/err")"
    fi
    echo "$line"
  done
  if [ "$(stat -c %s "$input")" -lt 400000 ]; then
    "$cli" "$input" "$work/out.ply" --complex "$work/complex.json" > /dev/null 2>&1 &&
      echo "$name complex: $(digest "$work/complex.json")"
  fi
done

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: bench/surface_quality.sh [OUT.md]  (its table goes into bench/surface_quality.md)
#
# The quality of pcl_wrap's default surface next to its raw W and to CGAL's Advancing Front,
# CGAL's Alpha_wrap_3 and PCL's GreedyProjection, on real models and scans from Debian's
# libcgal-demo and on a synthetic torus and terrain: a Markdown table (closed = watertight, every edge in two
# triangles; manifold = no non-manifold edge or vertex; share of the input points on the
# surface; Chamfer and Hausdorff distances to the reference mesh, relative to its diagonal, or to
# the input points where there is no mesh; time). Needs scripts/build.sh first.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bench=${PCL_WRAP_BENCH_DIR:-$here/../build/bench}
out=${1:-/dev/stdout}
archive=/usr/share/doc/libcgal-dev/data.tar.gz
data=$here/../data/fetched/quality
mkdir -p "$data"
files=(meshes/bunny00.off meshes/fandisk.off points_3/kitten.xyz meshes/cow.off meshes/bull.off
       meshes/triceratops.off meshes/knot1.off meshes/blobby.off meshes/anchor_dense.off
       meshes/man.off meshes/cheese.off points_3/oni.ply points_3/ball.ply points_3/sphere_20k.xyz)
for f in "${files[@]}"; do
  [ -s "$data/$(basename "$f")" ] || tar -xzf "$archive" -O "data/$f" > "$data/$(basename "$f")"
done
methods=(pcl_wrap pcl_wrap_raw cgal_advancing_front cgal_alpha_wrap pcl_greedy_projection)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
{
  echo "| dataset | method | triangles | closed | manifold | components | genus | points on it | Chamfer | Hausdorff | s |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  for source in "${files[@]/#/$data/}" torus terrain; do
    source=${source/#$data\/meshes\//$data/}
    source=${source/#$data\/points_3\//$data/}
    name=$(basename "$source")
    reference=points n=0
    case $source in
      *.off) reference=$source ;;
      torus) reference=torus n=20000 ;;
      terrain) n=5000 ;;
    esac
    for method in "${methods[@]}"; do
      if ! timeout 600 "$bench/bench_peers" "$method" "$source" "$n" 1 --mesh "$work/mesh.obj" > "$work/run.json" 2> /dev/null; then
        echo "| $name | $method | failed | | | | | | | | |"
        continue
      fi
      spec=$source
      [ "$n" = 0 ] || spec=$source:$n:1
      "$bench/mesh_quality" "$work/mesh.obj" "$spec" "$reference" 20000 > "$work/quality.json" 2> /dev/null || echo '{}' > "$work/quality.json"
      /usr/bin/python3 - "$name" "$method" "$work/run.json" "$work/quality.json" <<'PY'
import json, sys
name, method, run, quality = sys.argv[1:5]
r = json.loads(open(run).read().strip().splitlines()[-1])
q = json.loads(open(quality).read() or "{}")
manifold = q.get("nonmanifold_edges", 1) == 0 and q.get("nonmanifold_vertices", 1) == 0
yes = lambda b: "yes" if b else "no"
dist = lambda k: "%.4f" % q[k] if q.get(k, -1) >= 0 else "–"
genus = q.get("genus")
print(f"| {name} | {method} | {r['triangles']} | {yes(q.get('watertight'))} | {yes(manifold)} | {q.get('components', '–')} | "
      f"{'–' if genus is None else genus} | {100 * q.get('points_on_output', 0):.1f}% | {dist('chamfer')} | {dist('hausdorff')} | {r['seconds']:.2f} |")
PY
    done
  done
} > "$out"

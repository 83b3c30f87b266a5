#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reads a point cloud from a PLY file with Open3D, wraps it, and writes the surface.

usage: wrap_bunny.py [INPUT.ply [OUTPUT.ply]]
       (default: data/fetched/bunny00_points.ply, from scripts/fetch-data.sh, to
       out/bunny_wrap_python.ply; run with PYTHONPATH=build/python from a build tree)
"""
import os
import sys

import numpy as np
import open3d as o3d

import pcl_wrap

root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
source = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "data", "fetched", "bunny00_points.ply")
target = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "out", "bunny_wrap_python.ply")

cloud = o3d.io.read_point_cloud(source)
points = np.asarray(cloud.points)
if len(points) == 0:
    sys.exit("wrap_bunny.py: no points in %s" % source)

result = pcl_wrap.wrap(cloud)  # the default: a closed, oriented 2-manifold through the points
mesh = pcl_wrap.to_open3d(result)  # with the cloud's colours and normals, if it had them
if not mesh.has_vertex_normals():
    mesh.compute_vertex_normals()

os.makedirs(os.path.dirname(os.path.abspath(target)), exist_ok=True)
if not o3d.io.write_triangle_mesh(target, mesh):
    sys.exit("wrap_bunny.py: could not write %s" % target)
s = result.statistics
closed = mesh.is_edge_manifold(allow_boundary_edges=False) and mesh.is_vertex_manifold()
print("%s: %d points -> %d triangles, closed manifold: %s, %.2f s; wrote %s"
      % (source, len(points), len(result.triangles), closed, s["timings"]["total"], target))

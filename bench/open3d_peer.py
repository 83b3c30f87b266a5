#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: open3d_peer.py open3d_ball_pivoting|open3d_alpha_shape|open3d_poisson POINTS.xyz [--mesh OUT.obj]

Open3D's reconstructions (Debian's python3-open3d), timed from the points in memory, as one JSON
line like bench_peers'. Ball pivoting needs normals (estimated from 20 neighbours, timed apart
and included); its radii are 1.5, 3 and 6 times the median nearest-neighbour distance. The alpha
shape's alpha is 2 times that distance (as PCL ConcaveHull's here). Poisson reconstruction (depth 8)
takes the same normals, oriented consistently along a tangent-plane graph of 20 neighbours."""
import json
import resource
import sys
import time

import numpy as np
import open3d as o3d


def main():
    method, path = sys.argv[1], sys.argv[2]
    out = sys.argv[sys.argv.index("--mesh") + 1] if "--mesh" in sys.argv else None
    points = np.loadtxt(path, ndmin=2)
    o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Error)
    start = time.perf_counter()
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    spacing = float(np.median(cloud.compute_nearest_neighbor_distance()))
    normal_seconds = 0.0
    if method == "open3d_ball_pivoting":
        cloud.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(20))
        normal_seconds = time.perf_counter() - start
        radii = [1.5 * spacing, 3 * spacing, 6 * spacing]
        mesh = o3d.geometry.TriangleMesh.create_from_point_cloud_ball_pivoting(cloud, o3d.utility.DoubleVector(radii))
        note = "normals k 20; radii %.4g %.4g %.4g" % tuple(radii)
    elif method == "open3d_poisson":
        cloud.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(20))
        cloud.orient_normals_consistent_tangent_plane(20)
        normal_seconds = time.perf_counter() - start
        mesh, _ = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(cloud, depth=8)
        note = "normals k 20, oriented on a tangent-plane graph; depth 8"
    elif method == "open3d_alpha_shape":
        alpha = 2 * spacing
        mesh = o3d.geometry.TriangleMesh.create_from_point_cloud_alpha_shape(cloud, alpha)
        note = "alpha %.4g (2 x spacing)" % alpha
    else:
        sys.exit(f"open3d_peer.py: unknown method {method}")
    seconds = time.perf_counter() - start
    vertices, triangles = np.asarray(mesh.vertices), np.asarray(mesh.triangles)
    if out:
        with open(out, "w") as f:
            for v in vertices:
                f.write("v %.17g %.17g %.17g\n" % tuple(v))
            for t in triangles:
                f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))
    print(json.dumps({"method": method, "points": len(points), "seconds": seconds, "normal_seconds": normal_seconds,
                      "peak_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
                      "vertices": len(vertices), "triangles": len(triangles), "note": note}))


if __name__ == "__main__":
    main()

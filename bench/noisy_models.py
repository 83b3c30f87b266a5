#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/noisy_models.py BUILD_DIR N... [--noise K,K,...] [--seed S]

The default surface of the development meshes of Debian's libcgal-demo (bench/corpus.py's
resampled class) at N points each, uniform by area, moved by Gaussian noise of K times the
median spacing (0.25, 0.5 and 1 unless --noise says otherwise; bench/noisy_shapes.py draws the
same clouds). A Markdown table, a row per mesh and size, a column per noise: the surface's
components, genus, share of the points on it and time ("ok": one component, the mesh's genus and
at least 99% of the points). Uses BUILD_DIR/apps/pcl_wrap and BUILD_DIR/bench/mesh_quality.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402
import noisy_shapes  # noqa: E402


def main():
    args = sys.argv[1:]
    noise, seed = [0.25, 0.5, 1.0], 1
    for flag in ("--noise", "--seed"):
        if flag in args:
            i = args.index(flag)
            value = args[i + 1]
            del args[i:i + 2]
            if flag == "--noise":
                noise = [float(k) for k in value.split(",")]
            else:
                seed = int(value)
    if len(args) < 2:
        sys.exit(__doc__)
    build, sizes = os.path.abspath(args[0]), [int(n) for n in args[1:]]
    meshes = corpus.development_meshes()
    if not meshes:
        sys.exit("noisy_models.py: needs libcgal-demo")
    print("| model | expected | points | " + " | ".join("noise %g" % k for k in noise) + " |")
    print("|---|---|---|" + "---|" * len(noise))
    with tempfile.TemporaryDirectory() as work:
        cloud, mesh, stats = (os.path.join(work, f) for f in ("cloud.xyz", "mesh.obj", "stats.json"))
        for n in sizes:
            for name, vertices, triangles in meshes:
                genus = corpus.genus_of(vertices, triangles)
                cells = []
                for k in noise:
                    points, _ = noisy_shapes.draw(lambda: corpus.on_mesh(vertices, triangles, n), k, seed)
                    np.savetxt(cloud, points, fmt="%.9g")
                    subprocess.run([os.path.join(build, "apps", "pcl_wrap"), cloud, mesh, "--quiet", "--stats-json",
                                    stats], check=True)
                    q = json.loads(subprocess.run([os.path.join(build, "bench", "mesh_quality"), mesh, cloud, "points",
                                                   "500"], check=True, capture_output=True, text=True).stdout)
                    seconds = json.load(open(stats))["timings"]["total"]
                    right = q["components"] == 1 and q["genus"] == genus and q["points_on_output"] >= 0.99
                    cells.append("%sc%d g%s %.2f%% %.1fs" % ("**ok** " if right else "", q["components"], q["genus"],
                                                          100 * q["points_on_output"], seconds))
                print("| %s | c1 g%d | %d | %s |" % (name, genus, n, " | ".join(cells)), flush=True)


if __name__ == "__main__":
    main()

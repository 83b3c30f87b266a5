#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/far_blobs.py BUILD_DIR [SEEDS]

3,000 points of the unit sphere (radial noise of 1e-3) and a Gaussian blob of K points 5 units
away (deviation 0.02 or 0.1), from seeds 1 to SEEDS (default 6), for K from 1 (an outlier) to 400
(a small object). The default surface should leave a blob of fewer than 32 points off and report
it (docs/surface.md, "Points apart"), and make a larger blob a piece of its own ("Points that fill
a volume"): never a spike from the blob to the sphere. A Markdown table per K and deviation: how
many clouds come out right, and the pieces, longest edge and points apart of the others. Uses
BUILD_DIR/apps/pcl_wrap.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import single_layers  # noqa: E402

SIZES = (1, 3, 8, 20, 31, 32, 60, 100, 200, 400)
SPHERE = 3000


def cloud(size, sigma, seed):
    rng = np.random.default_rng(seed)
    p = rng.normal(size=(SPHERE, 3))
    p *= (1 + rng.uniform(-1e-3, 1e-3, (SPHERE, 1))) / np.linalg.norm(p, axis=1)[:, None]
    return np.vstack([p, np.array([5.0, 0, 0]) + sigma * rng.normal(size=(size, 3))])


def pieces_and_longest(mesh):
    """The connected pieces of the mesh's triangles and its longest edge."""
    v, t = single_layers.read_obj(mesh)
    parent = list(range(len(v)))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for a, b, c in t:
        parent[find(a)] = find(b)
        parent[find(a)] = find(c)
    edges = np.vstack([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    longest = float(np.linalg.norm(v[edges[:, 0]] - v[edges[:, 1]], axis=1).max()) if len(t) else 0.0
    return len({find(a) for a in t[:, 0]}), longest


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cli = os.path.join(sys.argv[1], "apps", "pcl_wrap")
    seeds = int(sys.argv[2]) if len(sys.argv) > 2 else 6
    print("| blob points | deviation | right | the others: pieces, longest edge, points apart |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        path, mesh, stats = (os.path.join(work, name) for name in ("c.xyz", "c.obj", "c.json"))
        for size in SIZES:
            for sigma in (0.02, 0.1):
                right, others = 0, []
                for seed in range(1, seeds + 1):
                    np.savetxt(path, cloud(size, sigma, seed), fmt="%.9g")
                    subprocess.run([cli, path, mesh, "--quiet", "--stats-json", stats], check=True)
                    pieces, longest = pieces_and_longest(mesh)
                    apart = json.load(open(stats))["points"]["apart"]
                    # Off and reported below 32 points, a piece of its own from 32 on; no spike.
                    expected = (1, size) if size < 32 else (2, 0)
                    if (pieces, apart) == expected and longest < 1.0:
                        right += 1
                    else:
                        others.append(f"seed {seed}: {pieces}, {longest:.2f}, {apart}")
                print(f"| {size} | {sigma} | {right} of {seeds} | {'; '.join(others) or '-'} |")


if __name__ == "__main__":
    main()

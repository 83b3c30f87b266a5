#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/far_outliers.py BUILD_DIR [CLOUDS]

Seeded clouds 1 to CLOUDS (default 100): a unit sphere or a torus of radii 1 and 0.3, 1,000 to
6,000 points moved by noise of up to half their median spacing, and 1 to 5 outliers 2 to 10 units
from the centre. Right: every outlier is off the default surface and reported apart (docs/surface.md,
"Points apart"), the surface is one closed, oriented 2-manifold of the shape's genus through at
least 99% of the shape's points, and it is not the paper's W. Prints how many clouds are right and,
for each of the others, what is wrong, with each outlier not reported apart, its distance to the
shape in its median spacings, and whether it is listed off the surface. Uses BUILD_DIR/apps/pcl_wrap.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402
import far_blobs  # noqa: E402
import surface_fuzz  # noqa: E402


def cloud(seed):
    """The shape's points, the outliers after them, the shape's genus and its median spacing."""
    rng = np.random.default_rng(seed)
    corpus.rng = rng
    n = int(rng.integers(1000, 6000))
    torus = rng.random() < 0.5
    shape = corpus.torus(n, 1.0, 0.3) if torus else corpus.sphere(n)
    spacing = corpus.median_spacing(shape)
    shape = corpus.noisy(shape, float(rng.uniform(0, 0.5)) * spacing)
    m = int(rng.integers(1, 6))
    directions = rng.normal(size=(m, 3))
    directions /= np.linalg.norm(directions, axis=1)[:, None]
    outliers = directions * rng.uniform(2.0, 10.0, size=(m, 1))
    return shape, outliers, int(torus), spacing


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cli = os.path.join(sys.argv[1], "apps", "pcl_wrap")
    clouds = int(sys.argv[2]) if len(sys.argv) > 2 else 100
    right, others = 0, []
    with tempfile.TemporaryDirectory() as work:
        path, mesh, stats = (os.path.join(work, name) for name in ("c.xyz", "c.obj", "c.json"))
        for seed in range(1, clouds + 1):
            shape, outliers, genus, spacing = cloud(seed)
            n = len(shape)
            np.savetxt(path, np.vstack([shape, outliers]), fmt="%.17g")
            subprocess.run([cli, path, mesh, "--quiet", "--stats-json", stats], check=True)
            s = json.load(open(stats))
            vertices, triangles = surface_fuzz.single_layers.read_obj(mesh)
            on = set(np.unique(triangles).tolist())
            pieces, _ = far_blobs.pieces_and_longest(mesh)
            euler = len(on) - len(triangles) * 3 // 2 + len(triangles)
            wrong = []
            problem = surface_fuzz.broken(vertices, triangles, False)
            if problem:
                wrong.append(problem)
            if s["surface_is_w"]:
                wrong.append("W")
            if pieces != 1 or euler != 2 - 2 * genus:
                wrong.append(f"{pieces} pieces, Euler characteristic {euler}")
            if len(on & set(range(n))) < 0.99 * n:
                wrong.append(f"{len(on & set(range(n)))} of {n} points on it")
            on_it = sorted(i for i in range(n, n + len(outliers)) if i in on)
            if on_it:
                wrong.append(f"outliers {on_it} on it")
            distances = cKDTree(shape).query(outliers)[0] / spacing
            not_apart = [i for i in range(n, n + len(outliers)) if i not in s["apart"]]
            if not_apart:
                listed = set(not_apart) <= set(s["off_surface"]) | on  # every point is on it or listed off
                wrong.append(f"outliers not reported apart, {', '.join(f'{distances[i - n]:.0f}' for i in not_apart)}"
                             f" spacings away ({'listed off the surface' if listed else 'NOT LISTED off the surface'})")
            if wrong:
                others.append(f"seed {seed}: {'; '.join(wrong)}")
            else:
                right += 1
    print(f"{right} of {clouds} clouds right")
    for line in others:
        print(f"- {line}")


if __name__ == "__main__":
    main()

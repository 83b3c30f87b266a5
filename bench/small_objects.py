#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/small_objects.py BUILD_DIR [SEEDS]

Twenty small ellipsoids laid out as the bones of a foot (five rays of three bones in a row along x,
0.2 apart from ray to ray, and five bones beside the rays' ends), sparsely sampled: 1,000 to 3,000
points in all, 33 to 226 a bone, the bones in a ray 0.12 or 0.2 apart (about 2.5 to 7.5 median
spacings). Each cloud is drawn from seeds 1 to SEEDS (default 20). A Markdown table: per size and
gap, the median spacing, how many default surfaces come out as the twenty bones (closed and
manifold, twenty components of genus 0, at least 99% of the points on them), and what the others
are. Uses BUILD_DIR/apps/pcl_wrap and BUILD_DIR/bench/mesh_quality.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402
import corpus_table  # noqa: E402

BONES = 20


def foot_of_bones(rng, n, gap):
    """The bones' points: n in all, each bone's by its size, at least 24."""
    shapes = []
    for ray in range(5):
        x = 0.0
        for length in (1.0, 0.5, 0.35):
            shapes.append(((x + length / 2, 0.5 * ray, 0.0), (length / 2, 0.15, 0.15)))
            x += length + gap
    for i in range(5):
        shapes.append(((-0.25 - gap - (0.4 + gap) * (i % 2), 0.5 * i, 0.0), (0.2, 0.2, 0.18)))
    sizes = np.array([a * b + b * c + a * c for _, (a, b, c) in shapes])
    counts = np.maximum(24, np.round(n * sizes / sizes.sum())).astype(int)
    out = []
    for (centre, axes), m in zip(shapes, counts):
        v = rng.normal(size=(m, 3))
        v /= np.linalg.norm(v, axis=1)[:, None]
        out.append(np.asarray(centre) + v * np.asarray(axes))
    return np.concatenate(out)


def surface(build, points, work):
    cloud, mesh = os.path.join(work, "bones.xyz"), os.path.join(work, "bones.obj")
    np.savetxt(cloud, points, fmt="%.9g")
    subprocess.run([os.path.join(build, "apps", "pcl_wrap"), cloud, mesh, "--quiet"], check=True)
    out = subprocess.run([os.path.join(build, "bench", "mesh_quality"), mesh, cloud, "none", "1000"], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    build, seeds = os.path.abspath(args[0]), int(args[1]) if len(args) > 1 else 20
    print("| points | gap | gap (median spacings) | right | the others |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for n in (1000, 1500, 3000):
            for gap in (0.12, 0.2):
                right, others, spacings = 0, [], []
                for seed in range(1, seeds + 1):
                    points = foot_of_bones(np.random.default_rng(seed), n, gap)
                    spacings.append(corpus.median_spacing(points))
                    q = surface(build, points, work)
                    if corpus_table.right(q, {"components": BONES, "genus": 0}, "pcl_wrap"):
                        right += 1
                    else:
                        others.append("c%d g%s %.1f%%" % (q["components"], q["genus"], 100 * q["points_on_output"]))
                print("| %d | %g | %.1f | %d of %d | %s |" % (n, gap, gap / np.median(spacings), right, seeds,
                                                             ", ".join(others) or "–"), flush=True)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/noisy_shapes.py SHAPE N K SEED OUT.xyz

Writes N points uniform by area on SHAPE, moved by isotropic Gaussian noise of K times the clean
sample's median spacing (its nearest-neighbour distance), drawn from SEED. SHAPE is sphere (the
unit sphere), torus (radii 1 and 0.3), or one of the development meshes of Debian's libcgal-demo
that bench/corpus.py resamples (knot1, anchor_dense, blobby, dino, fandisk, triceratops,
bunny00). The surface has one component, and the genus of the shape: the noise and resampled
classes of bench/corpus.py at any size. Prints the spacing, sigma and the shape's genus.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402  (its shapes, drawn from corpus.rng)


def draw(sample, k, seed):
    """The points sample() draws from SEED's generator, moved by noise of k times their median
    spacing, and that spacing."""
    corpus.rng = np.random.default_rng(seed)
    points = sample()
    spacing = corpus.median_spacing(points)
    return corpus.noisy(points, k * spacing), spacing


def main():
    shapes = ("sphere", "torus") + corpus.DEVELOPMENT_MESHES
    if len(sys.argv) != 6 or sys.argv[1] not in shapes:
        sys.exit(__doc__)
    shape, n, k, seed, out = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
    if shape == "sphere":
        sample, genus = (lambda: corpus.sphere(n)), 0
    elif shape == "torus":
        sample, genus = (lambda: corpus.torus(n)), 1
    else:
        meshes = {name: (vertices, triangles) for name, vertices, triangles in corpus.development_meshes()}
        if shape not in meshes:
            sys.exit("noisy_shapes.py: %s needs libcgal-demo" % shape)
        vertices, triangles = meshes[shape]
        sample, genus = (lambda: corpus.on_mesh(vertices, triangles, n)), corpus.genus_of(vertices, triangles)
    points, spacing = draw(sample, k, seed)
    np.savetxt(out, points, fmt="%.9g")
    print("spacing %.6g sigma %.6g genus %d" % (spacing, k * spacing, genus))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/noisy_shapes.py sphere|torus N K SEED OUT.xyz

Writes N points on the unit sphere, or on the torus of radii 1 and 0.3, uniform by area, moved by
isotropic Gaussian noise of K times the clean sample's median spacing (its nearest-neighbour
distance), drawn from SEED. The surface has one component, and genus 0 or 1: the noise class of
bench/corpus.py at any size. Prints the spacing and sigma.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402  (its shapes, drawn from corpus.rng)


def main():
    if len(sys.argv) != 6 or sys.argv[1] not in ("sphere", "torus"):
        sys.exit(__doc__)
    shape, n, k, seed, out = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
    corpus.rng = np.random.default_rng(seed)
    points = corpus.sphere(n) if shape == "sphere" else corpus.torus(n)
    spacing = corpus.median_spacing(points)
    np.savetxt(out, corpus.noisy(points, k * spacing), fmt="%.9g")
    print("spacing %.6g sigma %.6g" % (spacing, k * spacing))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: tests/noisy_models_check.py BUILD_DIR

The default surface on development meshes resampled with noise of up to a spacing, drawn as
bench/noisy_models.py draws them: cases where the noise leaves the labelling many small handles
close together, so that cutting some changes the surface around them and the handles left are
found only by looking there again (docs/surface.md, "Cutting small handles"); and thin tubes (a
knot, an anchor's arms) into which a chain of small, overlapping spheres crosses the noisy layer
and would carry the outside's label through the tube if a vote for the same side counted as much
as one for the other side (docs/surface.md, section 1); and a dino whose noisy leg touches its
belly, where mending a pinch by moving a fan of long tetrahedra across the gap would tie the two
by a web of many handles (docs/surface.md, section 2); and coarse dinos whose noise leaves a few
points beside the surface labelled a solid of their own, which X ties to the rest by edges alone,
and which would otherwise come out as a closed piece of its own (docs/surface.md, "Joining what
the labelling cut apart"); and a coarse dino whose first cut of a handle at a foot leaves a void
touching the surface at a vertex, which, counted as one part with the surface, would hide the
handle from the search that follows (docs/surface.md, "Cutting small handles"). Each must
come out closed, vertex-manifold, in one piece with the mesh's genus and at least 99% of the
points on it (bench/corpus_table.py's test). Uses BUILD_DIR/bench/bench_peers and mesh_quality.
"""
import os
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "bench"))
import corpus  # noqa: E402
import corpus_table  # noqa: E402
import noisy_shapes  # noqa: E402

CASES = [  # mesh, points, noise in median spacings, seed
    ("bunny00", 10000, 1.0, 1),
    ("dino", 100000, 1.0, 1),
    ("dino", 100000, 0.5, 1),
    ("anchor_dense", 10000, 1.0, 1),
    ("knot1", 10000, 1.0, 1),
    ("knot1", 10000, 1.0, 3),
    ("anchor_dense", 10000, 1.0, 3),
    ("dino", 10000, 0.25, 3),
    ("dino", 10000, 1.0, 4),
    ("dino", 10000, 0.5, 5),
    ("dino", 10000, 1.0, 5),
]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    build = os.path.abspath(sys.argv[1])
    meshes = {name: (vertices, triangles) for name, vertices, triangles in corpus.development_meshes()}
    if not meshes:
        sys.exit("no development meshes: is libcgal-demo installed (scripts/setup.sh)?")
    wrong = []
    with tempfile.TemporaryDirectory() as work:
        cloud = os.path.join(work, "cloud.xyz")
        for name, n, k, seed in CASES:
            vertices, triangles = meshes[name]
            points, _ = noisy_shapes.draw(lambda: corpus.on_mesh(vertices, triangles, n), k, seed)
            np.savetxt(cloud, points, fmt="%.9g")
            case = {"components": 1, "genus": corpus.genus_of(vertices, triangles)}
            q = corpus_table.run(build, "pcl_wrap", cloud, work)
            ok = corpus_table.right(q, case, "pcl_wrap")
            got = corpus_table.described(q)
            print("%-14s %7d noise %.2f seed %d  expected c1 g%d, got %s%s" % (name, n, k, seed, case["genus"], got,
                                                                            "" if ok else "  WRONG"))
            if not ok:
                wrong.append("%s %d %g seed %d" % (name, n, k, seed))
    if wrong:
        sys.exit("wrong: " + ", ".join(wrong))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/coarse_shapes.py BUILD_DIR [SEEDS]

Shapes of bench/corpus.py sampled ever more coarsely, where the default surface starts to lose
their topology: a flange coupling (genus 9; a hole's wall has about 34 points at 1,500 points in
all), a thin ring of tube radius 0.12 (genus 1; about seven points round the tube at 300 points)
and a mug (genus 1; its wall and bottom 0.15 thick, about three spacings at 3,000 points), whose
handle meets the wall at a grazing angle, and the same with a handle that meets it nearly square
on. Each cloud is drawn from seeds 1 to SEEDS (default 20). A Markdown table: per shape and size,
how many default surfaces come out right (closed and manifold, one piece of the shape's genus, at
least 99% of the points on it: bench/corpus_table.py's test) and the genera of all. Uses
BUILD_DIR/apps/pcl_wrap and BUILD_DIR/bench/mesh_quality.
"""
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402
import corpus_table  # noqa: E402
import small_objects  # noqa: E402

SHAPES = (("coupling", lambda n: corpus.coupling(n), 9, (1500, 2000, 3000)),
          ("thin ring", lambda n: corpus.torus(n, 1.0, 0.12), 1, (300, 400, 600)),
          ("mug", lambda n: corpus.mug(n), 1, (2000, 3000, 5000)),
          ("mug, square joints", lambda n: corpus.mug(n, 1.15), 1, (2000, 3000, 5000)))


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    build, seeds = os.path.abspath(args[0]), int(args[1]) if len(args) > 1 else 20
    print("| shape | points | right | genera |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for name, make, genus, sizes in SHAPES:
            for n in sizes:
                right, genera = 0, []
                for seed in range(1, seeds + 1):
                    corpus.rng = np.random.default_rng(seed)
                    q = small_objects.surface(build, make(n), work)
                    right += corpus_table.right(q, {"components": 1, "genus": genus}, "pcl_wrap")
                    genera.append("%s" % q["genus"] if q["components"] == 1 else "c%d" % q["components"])
                print("| %s | %d | %d of %d | %s |" % (name, n, right, seeds, " ".join(genera)), flush=True)


if __name__ == "__main__":
    main()

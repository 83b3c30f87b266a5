#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/cylinder_gaps.py BUILD_DIR [SEEDS] [--check]

Four thin capped cylinders side by side (bench/corpus.py's bridge case: radius 0.15, length 3,
2,500 points each, a median spacing of 0.0163), at gaps of 2.5, 3.1, 3.7 and 4.9 spacings, each
drawn from seeds 1 to SEEDS (default 5): how many of the default surfaces come out as the four
cylinders (closed, four components of genus 0, every point on them), and what the others are. A
Markdown table. With --check, exits with status 1 unless every cloud from seeds 1 to 5 at 3.7 and
4.9 spacings, and four of the five at 3.1, come out right (from seeds 1 to 10, three at 3.1
spacings do not). Uses BUILD_DIR/apps/pcl_wrap and BUILD_DIR/bench/mesh_quality.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402

SPACING = 0.0163
OFFSETS = (0.34, 0.35, 0.36, 0.38)  # cylinder axes this far apart: gaps of offset - 0.3


def cylinders(offset, seed):
    corpus.rng = np.random.default_rng(seed)
    return np.concatenate([corpus.capped_cylinder(2500, 0.15, 3.0, c=(offset * i, 0, 0)) for i in range(4)])


def surface(build, points, work):
    """(right, what) of the default surface of points."""
    cloud, mesh = os.path.join(work, "c.xyz"), os.path.join(work, "c.obj")
    np.savetxt(cloud, points, fmt="%.9g")
    subprocess.run([os.path.join(build, "apps", "pcl_wrap"), cloud, mesh], check=True, capture_output=True)
    out = subprocess.run([os.path.join(build, "bench", "mesh_quality"), mesh, cloud, "none", "1000"], check=True,
                         capture_output=True, text=True).stdout
    q = json.loads(out.strip().splitlines()[-1])
    right = (q["watertight"] and q["components"] == 4 and q["genus"] == 0 and q["points_on_output"] == 1.0)
    return right, "c%d g%s" % (q["components"], q["genus"])


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if not args:
        sys.exit(__doc__)
    build, seeds = os.path.abspath(args[0]), int(args[1]) if len(args) > 1 else 5
    wrong_checked = []  # (gap, seed) wrong from seeds 1 to 5: at 3.1 spacings, when two or more are
    print("| gap (spacings) | right | the others |")
    print("|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for offset in OFFSETS:
            results = [surface(build, cylinders(offset, seed), work) for seed in range(1, seeds + 1)]
            others = ", ".join(what for ok, what in results if not ok) or "–"
            gap = (offset - 0.3) / SPACING
            print("| %.1f | %d of %d | %s |" % (gap, sum(ok for ok, _ in results), seeds, others))
            wrong = [(gap, seed) for seed, (ok, _) in enumerate(results[:5], 1) if not ok]
            if gap > 3.5 or (gap > 3 and len(wrong) > 1):
                wrong_checked += wrong
    if "--check" in sys.argv and wrong_checked:
        sys.exit("cylinders tied: " + ", ".join("%.1f spacings apart, seed %d" % w for w in wrong_checked))


if __name__ == "__main__":
    main()

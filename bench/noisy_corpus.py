#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/noisy_corpus.py BUILD_DIR [SEEDS] [--seeds S,S,...] [--noise K,K,...] [--cases NAME,NAME,...]
                               [--keep DIR] [--check]

The synthetic shapes of bench/corpus.py (voids, parts, holes, bridges, separate objects, outliers)
with Gaussian noise of K times their median spacing (0.25, 0.5 and 1 unless --noise says
otherwise), each drawn from seeds 1 to SEEDS (default 5), or from the seeds --seeds lists. A
Markdown table, a row per case, a column per noise: how many default surfaces come out right (closed and manifold, the case's
components and genus, at least 99% of the points on it: bench/corpus_table.py's test), and what
the others are (components, genus, share of the points on the surface). With --keep, each cloud
is also written to DIR/CASE_noise_K_seed_S.xyz (for bench/corpus_pictures.sh). With --check, exits
with status 1 unless every surface is right. Uses
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

# Classes whose cases are noise-free shapes; the noise class and the resampled meshes carry
# noise of their own (bench/noisy_shapes.py, bench/noisy_models.py).
CLASSES = ("voids", "parts", "holes", "bridges", "separate", "degenerate")


def option(args, flag, default):
    if flag not in args:
        return default
    i = args.index(flag)
    value = args[i + 1]
    del args[i:i + 2]
    return value.split(",")


def main():
    args = sys.argv[1:]
    noise = [float(k) for k in option(args, "--noise", ["0.25", "0.5", "1"])]
    names = option(args, "--cases", None)
    keep = option(args, "--keep", [None])[0]
    check = "--check" in args
    if check:
        args.remove("--check")
    listed = option(args, "--seeds", None)
    if not args:
        sys.exit(__doc__)
    build = os.path.abspath(args[0])
    seeds = [int(s) for s in listed] if listed else list(range(1, (int(args[1]) if len(args) > 1 else 5) + 1))
    cases = [c for c in corpus.cases(True) if c[0] in CLASSES and (names is None or c[1] in names)]
    print("| class | case | points | expected | " + " | ".join("noise %g" % k for k in noise) + " |")
    print("|---|---|---|---|" + "---|" * len(noise))
    wrong = []  # (case, noise, seed)
    with tempfile.TemporaryDirectory() as work:
        for cls, name, make, components, genus in cases:
            cells, points = [], 0
            for k in noise:
                right, others = 0, []
                for seed in seeds:
                    corpus.rng = np.random.default_rng(seed)
                    p = make()
                    points = len(p)
                    p = corpus.noisy(p, k * corpus.median_spacing(p))
                    if keep:
                        os.makedirs(keep, exist_ok=True)
                        np.savetxt(os.path.join(keep, "%s_noise_%g_seed_%d.xyz" % (name, k, seed)), p, fmt="%.9g")
                    q = small_objects.surface(build, p, work)
                    if corpus_table.right(q, {"components": components, "genus": genus}, "pcl_wrap"):
                        right += 1
                    else:
                        others.append("c%d g%s %.1f%%" % (q["components"], q["genus"], 100 * q["points_on_output"]))
                        wrong.append((name, k, seed))
                cells.append("%d of %d%s" % (right, len(seeds), ": " + ", ".join(others) if others else ""))
            print("| %s | %s | %d | c%d g%d | %s |" % (cls, name, points, components, genus, " | ".join(cells)),
                  flush=True)
    if check and wrong:
        sys.exit("wrong: " + ", ".join("%s with noise %g, seed %d" % w for w in wrong))


if __name__ == "__main__":
    main()

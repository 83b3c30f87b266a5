#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/surface_fuzz.py BUILD_DIR [CASES] [--first SEED]

Random clouds through the CLI, CASES per family (default 100) from seeds SEED on (default 1): a
few dozen scattered points (Gaussian or uniform), small structured and degenerate sets (spheres,
tori, clusters, lattice subsets, a box's surface grid, a jittered grid, a thin slab, a far
outlier), mid-size shapes of bench/corpus.py with noise of up to a spacing, duplicates and
outliers, and single layers (terrains, spherical caps, half cylinders, slabs), by default and
with --closed. Checks that every run succeeds and that its surface is what docs/surface.md
promises: a closed, oriented 2-manifold (every edge on two triangles, once each way, every
vertex's triangles one fan), or for a single layer by default one oriented sheet, through at
least as many input points as the paper's W (--raw), but for the points apart from all others that
it leaves off (outliers), and with every other point it leaves off listed ("off_surface"); the
last column counts the surfaces through fewer. A Markdown table per family; exits with status 1
if a run fails or a surface breaks a promise. Uses BUILD_DIR/apps/pcl_wrap.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402
import single_layers  # noqa: E402


def tiny(rng):
    n = int(rng.integers(5, 81))
    return rng.normal(size=(n, 3)) if rng.random() < 0.5 else rng.random((n, 3))


def small(rng):
    kind, n = int(rng.integers(0, 9)), int(rng.integers(8, 400))
    if kind == 0:
        return corpus.sphere(n)
    if kind == 1:
        return corpus.torus(n, 1.0, 0.3)
    if kind == 2:
        return corpus.noisy(corpus.sphere(n), 0.05)
    if kind == 3:
        return np.r_[0.1 * rng.normal(size=(n // 2, 3)), 0.1 * rng.normal(size=(n - n // 2, 3)) + [1, 0, 0]]
    m = int(rng.integers(3, 9))
    grid = np.mgrid[0:m, 0:m, 0:m].reshape(3, -1).T.astype(float)
    if kind == 4:
        return grid[rng.random(len(grid)) < 0.6]
    if kind == 5:
        return grid[(grid == 0).any(1) | (grid == m - 1).any(1)]
    if kind == 6:
        return grid + 1e-9 * rng.normal(size=grid.shape)
    if kind == 7:
        return rng.random((n, 3)) * [1, 1, 0.01]
    return np.r_[rng.normal(size=(n, 3)), [[100.0, 100.0, 100.0]]]


def mid(rng):
    kind, n = int(rng.integers(0, 6)), int(rng.integers(500, 8000))
    if kind == 0:
        p = corpus.sphere(n)
    elif kind == 1:
        p = corpus.torus(n, 1.0, 0.3)
    elif kind == 2:
        p = np.r_[corpus.sphere(n // 2), corpus.torus(n - n // 2, 1.0, 0.3, c=(float(rng.uniform(1.5, 3)), 0, 0))]
    elif kind == 3:
        p = corpus.capped_cylinder(n, 0.2, 2.0)
    elif kind == 4:
        p = corpus.cup(n, 0.1)
    else:
        p = np.r_[corpus.sphere(n // 2), corpus.sphere(n - n // 2, r=0.5)]
    p = corpus.noisy(p, float(rng.choice([0, 0.25, 0.5, 1.0])) * corpus.median_spacing(p))
    if rng.random() < 0.3:
        p = np.r_[p, p[rng.integers(0, len(p), 20)]]  # duplicates
    if rng.random() < 0.3:
        p = np.r_[p, 5 * rng.normal(size=(3, 3))]  # outliers
    return p


def layer(rng):
    kind, n = int(rng.integers(0, 4)), int(rng.integers(50, 6000))
    if kind == 0:
        xy = rng.random((n, 2))
        p = np.c_[xy, 0.1 * np.sin(6 * xy[:, 0]) * np.cos(4 * xy[:, 1])]
    elif kind == 1:
        v = corpus.sphere(n)
        p = v[v[:, 2] > float(rng.uniform(-0.5, 0.8))]
    elif kind == 2:
        p = np.c_[rng.random((n, 2)), 0.02 * rng.random(n)]
    else:
        t, z = np.pi * rng.random(n), rng.random(n)
        p = np.c_[np.cos(t), np.sin(t), z]
    return p + float(rng.choice([0, 0.1, 0.3])) / np.sqrt(len(p)) * rng.normal(size=p.shape)


FAMILIES = (("a few dozen scattered points", tiny, []), ("small and degenerate", small, []),
            ("mid-size shapes, noise, duplicates, outliers", mid, []), ("single layers", layer, []),
            ("single layers, --closed", layer, ["--closed"]))


def broken(vertices, triangles, sheet):
    """What breaks the promise, or None (single_layers.describe()'s checks)."""
    d = single_layers.describe(vertices, triangles, len(vertices))
    if not d["manifold"]:
        return "not a manifold"
    if not d["oriented"]:
        return "not oriented"
    if d["open"] and not sheet:
        return "not closed"
    return None


def run(build, points, extra, work):
    """(problem or None, fewer points on it than on W)."""
    cloud = os.path.join(work, "c.xyz")
    np.savetxt(cloud, points, fmt="%.17g")
    out, raw, stats = (os.path.join(work, name) for name in ("d.obj", "r.obj", "s.json"))
    app = os.path.join(build, "apps", "pcl_wrap")
    done = subprocess.run([app, cloud, out, "--quiet", "--stats-json", stats] + extra, capture_output=True, text=True)
    if done.returncode != 0:
        return "exit status %d: %s" % (done.returncode, done.stderr.strip()[-200:]), False
    subprocess.run([app, cloud, raw, "--quiet", "--raw"], check=True)
    with open(stats) as f:
        s = json.load(f)
    vertices, tris = single_layers.read_obj(out)
    used, copies = s["points"]["input"] - s["points"]["skipped"], s["manifold"]["copies"]
    on = {v if v < used else copies[v - used] for v in np.unique(tris).tolist()}
    on_w = set(np.unique(single_layers.read_obj(raw)[1]).tolist()) - set(s["apart"])
    problem = None
    if s["triangulation_dimension"] == 3 and len(tris):
        problem = broken(vertices, tris, s["manifold"]["single_layer"] and "--closed" not in extra)
    # Every point given is on the surface, listed off it, or skipped, a duplicate or hidden.
    p, off = s["points"], set(s["off_surface"])
    if not problem and (on & off or len(on) + len(off) + p["skipped"] + p["duplicate"] + p["hidden"] != p["input"]):
        problem = "points unaccounted for: %d on, %d off, of %d" % (len(on), len(off), p["input"])
    return problem, len(on) < len(on_w)


def main():
    args, first = sys.argv[1:], 1
    if "--first" in args:
        i = args.index("--first")
        first = int(args[i + 1])
        del args[i:i + 2]
    if not args:
        sys.exit(__doc__)
    build = os.path.abspath(args[0])
    cases = int(args[1]) if len(args) > 1 else 100
    print("| family | clouds | broken promises | fewer points than W |")
    print("|---|---|---|---|")
    failed = False
    with tempfile.TemporaryDirectory() as work:
        for name, draw, extra in FAMILIES:
            problems, fewer = [], 0
            for seed in range(first, first + cases):
                rng = np.random.default_rng(seed)
                corpus.rng = rng
                problem, less = run(build, draw(rng), extra, work)
                fewer += less
                if problem:
                    problems.append("seed %d: %s" % (seed, problem))
            failed = failed or bool(problems) or fewer > 0
            print("| %s | %d | %s | %d |" % (name, cases, "; ".join(problems) or "none", fewer), flush=True)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/corpus_table.py CORPUS_DIR [BUILD_DIR] [--methods=m1,m2,...]

Runs each method of bench_peers on every case of a corpus written by bench/corpus.py and prints
two Markdown tables: every case (components, genus, share of the points on the surface, seconds)
and, per class, how many cases came out right: closed and manifold, the expected components and
genus, and (for the methods that pass through the points) at least 99% of the points on the
surface. Methods: pcl_wrap (the default surface), pcl_wrap_raw (the paper's W),
cgal_advancing_front, cgal_alpha_wrap and the others bench_peers knows, and open3d_poisson
(bench/open3d_peer.py); default pcl_wrap,pcl_wrap_raw.
"""
import json
import os
import subprocess
import sys
import tempfile


def run(build, method, cloud, work):
    mesh = os.path.join(work, "mesh.obj")
    if method.startswith("open3d_"):
        command = ["/usr/bin/python3", os.path.join(os.path.dirname(os.path.abspath(__file__)), "open3d_peer.py"),
                   method, cloud, "--mesh", mesh]
    else:
        command = [os.path.join(build, "bench", "bench_peers"), method, cloud, "0", "1", "--mesh", mesh]
    try:
        out = subprocess.run(command, capture_output=True, text=True, timeout=900)
    except subprocess.TimeoutExpired:
        return None
    if out.returncode != 0:
        return None
    seconds = json.loads(out.stdout.strip().splitlines()[-1])["seconds"]
    q = subprocess.run([os.path.join(build, "bench", "mesh_quality"), mesh, cloud, "points", "2000"],
                       capture_output=True, text=True)
    if q.returncode != 0:
        return None
    quality = json.loads(q.stdout.strip().splitlines()[-1])
    quality["seconds"] = seconds
    return quality


# These approximate the points rather than pass through them: their points on the surface are not counted.
APPROXIMATING = {"cgal_alpha_wrap", "open3d_poisson"}


def right(q, case, method):
    return (q is not None and q.get("watertight") and q.get("nonmanifold_vertices", 1) == 0
            and q.get("components") == case["components"] and q.get("genus") == case["genus"]
            and (method in APPROXIMATING or q.get("points_on_output", 0) >= 0.99))


def described(q):
    """What a run's surface came out as, for the checks' reports: pieces, genus, points on it."""
    if q is None:
        return "failed"
    return "c%s g%s %.2f%% of the points" % (q.get("components"), q.get("genus"), 100 * q.get("points_on_output", 0))


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if not args:
        sys.exit(__doc__)
    corpus = args[0]
    build = args[1] if len(args) > 1 else os.path.join(os.path.dirname(__file__), "..", "build")
    methods = ["pcl_wrap", "pcl_wrap_raw"]
    for a in sys.argv[1:]:
        if a.startswith("--methods="):
            methods = a.split("=", 1)[1].split(",")
    cases = json.load(open(os.path.join(corpus, "manifest.json")))
    results = {}
    with tempfile.TemporaryDirectory() as work:
        for case in cases:
            cloud = os.path.join(corpus, case["name"] + ".xyz")
            for m in methods:
                results[case["name"], m] = run(build, m, cloud, work)
    print("| class | case | points | expected | " + " | ".join(methods) + " |")
    print("|---|---|---|---|" + "---|" * len(methods))
    for case in cases:
        cells = []
        for m in methods:
            q = results[case["name"], m]
            if q is None:
                cells.append("failed")
                continue
            genus = "–" if q.get("genus") is None else q["genus"]
            mark = "**ok**" if right(q, case, m) else ""
            cells.append("%s c%d g%s %.1f%% %.2fs" % (mark, q.get("components", 0), genus,
                                                       100 * q.get("points_on_output", 0), q["seconds"]))
        print("| %s | %s | %d | c%d g%d | %s |" % (case["class"], case["name"], case["points"], case["components"],
                                                  case["genus"], " | ".join(cells)))
    print()
    print("| class | cases | " + " | ".join(methods) + " |")
    print("|---|---|" + "---|" * len(methods))
    classes = []
    for case in cases:
        if case["class"] not in classes:
            classes.append(case["class"])
    for k in classes:
        mine = [c for c in cases if c["class"] == k]
        print("| %s | %d | %s |" % (k, len(mine), " | ".join(
            str(sum(right(results[c["name"], m], c, m) for c in mine)) for m in methods)))


if __name__ == "__main__":
    main()

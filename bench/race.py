#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Time against quality: pcl_wrap's default and raw outputs next to the peers at several settings.

usage: bench/race.py [--datasets sphere,torus,kitten,bunny,fandisk,cow,bull] [--points 100000]
                     [--timeout 300] [--out bench/race.md] [--report-only]

CGAL Alpha_wrap_3 runs at alphas from the bounding box diagonal / 20 (CGAL's example) down to
2 x the median spacing, with offset alpha / 30, and at diagonal / 100 with offsets alpha / 10 and
alpha / 100; CGAL Advancing Front, PCL GreedyProjection and Open3D ball pivoting with the settings
of bench/compare.py. Each method runs once, in a process of its own, on the same points, with CGAL's
regular triangulation of them (the floor) in the same run. For each dataset: a table, a plot of time
against Chamfer and against Hausdorff distance (bench/plots/race_<dataset>.png), and who is fastest
at pcl_wrap's quality: a section of BENCHMARK.md (bench/compare.py puts it there). Needs
scripts/build.sh and scripts/fetch-data.sh first."""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare  # noqa: E402  (the runner and quality measurement shared with the speed tables)

HERE = compare.HERE
ROOT = compare.ROOT
ALPHA_WRAPS = ([f"cgal_alpha_wrap:diag/{d}:alpha/30" for d in (20, 50, 100, 200)]
               + [f"cgal_alpha_wrap:spacing*{s}:alpha/30" for s in (3, 2)]
               + ["cgal_alpha_wrap:diag/100:alpha/10", "cgal_alpha_wrap:diag/100:alpha/100"])
METHODS = (["floor_regular", "pcl_wrap", "pcl_wrap_raw", "cgal_advancing_front", "pcl_greedy_projection",
            "open3d_ball_pivoting"] + ALPHA_WRAPS)
MODELS = {"kitten": ("kitten.xyz", "points"), "bunny": ("bunny00.off", "mesh"), "fandisk": ("fandisk.off", "mesh"),
          "cow": ("cow.off", "mesh"), "bull": ("bull.off", "mesh")}
# Within this factor of pcl_wrap's Chamfer and Hausdorff distances counts as the same quality.
SAME_QUALITY = 1.1


def label(method):
    if method.startswith("cgal_alpha_wrap:"):
        _, alpha, offset = method.split(":")
        return f"Alpha_wrap_3 {alpha.replace('diag', 'diagonal').replace('*', ' x ')}, offset {offset}"
    return {"pcl_wrap": "pcl_wrap (default)", "pcl_wrap_raw": "pcl_wrap --raw"}.get(
        method, compare.LABEL.get(method, method).replace("**", ""))


def datasets(names, n):
    out = []
    for name in names:
        if name in ("sphere", "torus"):
            compare.DATASET_REFERENCE[name] = name
            out.append((f"{name} {n:,}", name, n))
        else:
            file, reference = MODELS[name]
            path = os.path.join(ROOT, "data", "fetched", "quality", file)
            compare.DATASET_REFERENCE[path] = path if reference == "mesh" else "points"
            out.append((name, path, 0))
    return out


def run(args):
    rows = []
    for name, source, n in datasets(args.datasets, args.points):
        with tempfile.TemporaryDirectory() as work:
            subprocess.run([os.path.join(compare.BENCH, "bench_peers"), "floor_delaunay", source, str(n), "1",
                            "--points", os.path.join(work, "points.xyz")], check=True, capture_output=True)
            for method in METHODS:
                r = compare.run_method(method, source, n, work, args.timeout)
                r["dataset"] = name
                rows.append(r)
                print(json.dumps(r), flush=True)
    return rows


def fastest_at_our_quality(rs):
    """The verdict for one dataset: the peers at least as good as pcl_wrap's default output (within
    SAME_QUALITY on both distances), fastest first, and how pcl_wrap's time compares."""
    ours = next((r for r in rs if r["method"] == "pcl_wrap" and r.get("chamfer")), None)
    if ours is None:
        return "no measurement of pcl_wrap's output"
    peers = [r for r in rs if not r["method"].startswith("pcl_wrap") and r.get("chamfer") is not None
             and r["chamfer"] <= SAME_QUALITY * ours["chamfer"] and r["hausdorff"] <= SAME_QUALITY * ours["hausdorff"]]
    peers.sort(key=lambda r: r["seconds"])
    if not peers:
        return (f"No peer setting comes within {SAME_QUALITY:g}x of pcl_wrap's Chamfer and Hausdorff distances "
                f"(Chamfer {ours['chamfer']:.3g}, Hausdorff {ours['hausdorff']:.3g}); pcl_wrap took {ours['seconds']:.3g} s")
    best = peers[0]
    verdict = "pcl_wrap is faster" if ours["seconds"] < best["seconds"] else f"{label(best['method'])} is faster"
    return (f"At pcl_wrap's quality (Chamfer {ours['chamfer']:.3g}, Hausdorff {ours['hausdorff']:.3g}) {verdict}: pcl_wrap "
            f"{ours['seconds']:.3g} s, the fastest such peer {label(best['method'])} {best['seconds']:.3g} s "
            f"({best['chamfer']:.3g}, {best['hausdorff']:.3g}; {len(peers)} peer setting{'s' if len(peers) > 1 else ''} "
            f"at that quality)")


def plot(name, rs, directory):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, key, title in ((axes[0], "chamfer", "Chamfer"), (axes[1], "hausdorff", "Hausdorff")):
        wraps = [r for r in rs if r["method"].startswith("cgal_alpha_wrap:") and r.get(key) is not None]
        if wraps:
            ax.plot([r["seconds"] for r in wraps], [r[key] for r in wraps], "s", color="tab:gray",
                    label="Alpha_wrap_3 (alpha, offset as marked)")
        for r in wraps:
            _, alpha, offset = r["method"].split(":")
            mark = alpha.replace("diag", "d").replace("spacing*", "") + ("s" if "spacing" in alpha else "")
            ax.annotate(mark + ("" if offset == "alpha/30" else " o" + offset[5:]), (r["seconds"], r[key]),
                        fontsize=6, xytext=(3, 3), textcoords="offset points")
        for r in rs:
            if r.get(key) is None or r["method"].startswith("cgal_alpha_wrap:") or "seconds" not in r:
                continue
            ours = r["method"].startswith("pcl_wrap")
            ax.plot([r["seconds"]], [r[key]], "*" if ours else "o", markersize=14 if ours else 8,
                    label=label(r["method"]))
        floor = compare.regular_floor(rs)
        if floor:
            ax.axvline(floor["seconds"], color="k", linewidth=0.8, linestyle="--", label="regular triangulation (floor)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("seconds")
        ax.set_ylabel(f"{title} distance / diagonal")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_title(f"{name}: time against {title} distance")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    path = os.path.join(directory, "race_" + name.split()[0] + ".png")
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def report(rows, out):
    by_dataset = {}
    for r in rows:
        by_dataset.setdefault(r["dataset"], []).append(r)
    lines = ["## Time against quality", "",
             "pcl_wrap's default and raw outputs next to each peer at the settings a user would try, on the same",
             "points in one run (CGAL Alpha_wrap_3 from a coarse alpha, the bounding box diagonal / 20, down to",
             "2 x the median spacing, and three offsets; marked d/D for diagonal / D, Ss for S x spacing, oR for",
             "offset alpha / R, else alpha / 30), each in a process of its own, run once. Lower left is",
             "better: less time and less distance to the reference surface (relative to the diagonal). Same",
             f"quality means within {SAME_QUALITY:g}x of pcl_wrap's Chamfer and Hausdorff distances.",
             "Reproduce: `scripts/build.sh && scripts/fetch-data.sh && bench/race.py`.", ""]
    for name, rs in by_dataset.items():
        picture = plot(name, rs, os.path.join(HERE, "plots"))
        floor = compare.regular_floor(rs)
        lines += [f"### {name}", "", fastest_at_our_quality(rs) + ".", "",
                  f"![]({os.path.relpath(picture, ROOT)})", "",
                  "| method | s | × floor | triangles | closed | components | genus | points on it | Chamfer | Hausdorff |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        for r in rs:
            if r["method"] == "floor_regular":
                continue
            if "error" in r:
                lines.append(f"| {label(r['method'])} | {r['error']} | | | | | | | | |")
                continue
            ratio = compare.fmt(r["seconds"] / floor["seconds"], "{:.2f}") if floor else "-"
            closed = "yes" if r.get("watertight") else "no"
            genus = "-" if r.get("genus") is None else str(r["genus"])
            on = compare.fmt(r.get("points_on_output"), "{:.1%}")
            lines.append(f"| {label(r['method'])} | {compare.fmt(r['seconds'])} | {ratio} | {r['triangles']} | {closed} | "
                         f"{r.get('components', '-')} | {genus} | {on} | {compare.fmt(r.get('chamfer'), '{:.3g}')} | "
                         f"{compare.fmt(r.get('hausdorff'), '{:.3g}')} |")
        lines.append("")
    with open(out, "w") as f:
        f.write("\n".join(lines))
    print(f"wrote {out}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--datasets", default="sphere,torus,kitten,bunny,fandisk,cow,bull")
    parser.add_argument("--points", type=int, default=100000, help="points on the sphere and the torus")
    parser.add_argument("--timeout", type=int, default=300)
    parser.add_argument("--out", default=os.path.join(HERE, "race.md"))
    parser.add_argument("--report-only", action="store_true", help="rewrite the report from bench/race.json")
    args = parser.parse_args()
    args.datasets = [d for d in args.datasets.split(",") if d]
    unknown = [d for d in args.datasets if d not in MODELS and d not in ("sphere", "torus")]
    if unknown:
        parser.error(f"unknown datasets {unknown}")
    rows = compare.saved_or_measured(os.path.join(HERE, "race.json"), args.report_only, lambda: run(args))
    report(rows, args.out)


if __name__ == "__main__":
    main()

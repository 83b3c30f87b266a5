#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Time and memory per point from 10,000 to millions of points.

usage: bench/scaling.py [--sizes 10000,100000,1000000,5000000] [--shapes sphere,torus,cube]
                        [--largest 10000000] [--timeout 900] [--name scaling] [--report-only]

pcl_wrap's default and raw outputs and CGAL's regular triangulation of the same points (the floor),
each in a process of its own, once per size, with as much memory as the last peak written and freed
before each run (see compare.warm_memory). --largest runs pcl_wrap's default output alone on that
many sphere points. Writes a table (microseconds and bytes of peak resident memory per point) and
bench/plots/NAME.png to bench/NAME.md, the measurements to bench/NAME.json: a section of
BENCHMARK.md (bench/compare.py puts bench/scaling.md there). The single layers:
`bench/scaling.py --shapes terrain,rough_terrain,half_sphere --largest 0 --name scaling_single_layers`.
Needs scripts/build.sh first."""
import argparse
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare  # noqa: E402

HERE = compare.HERE
ROOT = compare.ROOT
METHODS = ["floor_regular", "pcl_wrap", "pcl_wrap_raw"]
SHAPE_ORDER = ["sphere", "torus", "cube", "terrain", "rough_terrain", "half_sphere"]
LABEL = {"floor_regular": "regular triangulation (floor)", "pcl_wrap": "pcl_wrap (default)",
         "pcl_wrap_raw": "pcl_wrap --raw"}


def run(args):
    rows = []
    plan = [(shape, n, METHODS) for shape in args.shapes for n in args.sizes]
    if args.largest:
        plan.append(("sphere", args.largest, ["pcl_wrap"]))
    warm = 0
    for shape, n, methods in plan:
        with tempfile.TemporaryDirectory() as work:
            for method in methods:
                compare.warm_memory(min(warm, compare.available_memory() // 2))
                r = compare.run_method(method, shape, n, work, args.timeout, quality=False)
                r.update(shape=shape, n=n)
                if "peak_mib" in r:
                    warm = max(warm, int(r["peak_mib"] * 2 ** 20))
                rows.append(r)
                print(json.dumps(r), flush=True)
    return rows


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    shapes = sorted({r["shape"] for r in rows}, key=SHAPE_ORDER.index)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for shape, color in zip(shapes, ("tab:blue", "tab:orange", "tab:green")):
        for method, style in (("pcl_wrap", "-o"), ("pcl_wrap_raw", "--s"), ("floor_regular", ":^")):
            pts = sorted((r["n"], r) for r in rows if r["shape"] == shape and r["method"] == method and "seconds" in r)
            if not pts:
                continue
            xs = [n for n, _ in pts]
            axes[0].plot(xs, [r["seconds"] / n * 1e6 for n, r in pts], style, color=color,
                         label=f"{shape}: {LABEL[method]}")
            axes[1].plot(xs, [r["peak_mib"] * 2 ** 20 / n for n, r in pts], style, color=color,
                         label=f"{shape}: {LABEL[method]}")
    for ax, title in ((axes[0], "microseconds per point"), (axes[1], "peak resident bytes per point")):
        ax.set_xscale("log")
        ax.set_xlabel("points")
        ax.set_ylabel(title)
        ax.set_ylim(bottom=0)
        ax.grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def report(rows, name):
    out = os.path.join(HERE, name + ".md")
    picture = os.path.join(HERE, "plots", name + ".png")
    plot(rows, picture)
    single = name != "scaling"
    lines = ["## Time and memory per point" + (": single layers" if single else ""), "",
             "pcl_wrap's default and raw outputs and CGAL's regular triangulation of the same points, each in",
             "a process of its own, once per size (peak resident memory of that process). Reproduce:",
             "`scripts/build.sh && bench/scaling.py" + (f" --shapes {','.join(sorted({r['shape'] for r in rows}, key=SHAPE_ORDER.index))} --largest 0 --name {name}" if single else "") + "`.", "",
             f"![]({os.path.relpath(picture, ROOT)})", "",
             "| points | method | s | µs per point | × floor | peak MiB | bytes per point |",
             "|---|---|---|---|---|---|---|"]
    floors = {(r["shape"], r["n"]): r for r in rows if r["method"] == "floor_regular" and "seconds" in r}
    for r in rows:
        name = f"{r['shape']} {r['n']:,}"
        if "error" in r:
            lines.append(f"| {name} | {LABEL[r['method']]} | {r['error']} | | | | |")
            continue
        floor = floors.get((r["shape"], r["n"]))
        ratio = compare.fmt(r["seconds"] / floor["seconds"], "{:.2f}") if floor and r["method"] != "floor_regular" else "-"
        lines.append(f"| {name} | {LABEL[r['method']]} | {compare.fmt(r['seconds'])} | "
                     f"{r['seconds'] / r['n'] * 1e6:.2f} | {ratio} | {r['peak_mib']:.0f} | "
                     f"{r['peak_mib'] * 2 ** 20 / r['n']:.0f} |")
    # The default output against the raw run of the same points: what the surface stage costs.
    raw = {(r["shape"], r["n"]): r for r in rows if r["method"] == "pcl_wrap_raw" and "seconds" in r}
    pairs = [(r, raw[(r["shape"], r["n"])]) for r in rows
             if r["method"] == "pcl_wrap" and "seconds" in r and (r["shape"], r["n"]) in raw]
    if pairs:
        lines += ["", "The default output against `--raw` on the same points (one run each: rerun a pair with",
                  "`farm-bench -n 4 --vs 'build/apps/pcl_wrap POINTS OUT.ply --raw' -- build/apps/pcl_wrap POINTS OUT.ply`",
                  "for the spread):", "", "| points | time × raw | peak memory × raw |", "|---|---|---|"]
        lines += [f"| {d['shape']} {d['n']:,} | {d['seconds'] / w['seconds']:.2f} | {d['peak_mib'] / w['peak_mib']:.2f} |"
                  for d, w in pairs]
    largest = max((r for r in rows if r["method"] == "pcl_wrap" and "seconds" in r), key=lambda r: r["n"], default=None)
    if largest and not single:
        per_point = largest["peak_mib"] * 2 ** 20 / largest["n"]
        memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
        lines += ["", f"The largest cloud run, {largest['n']:,} sphere points, peaked at {largest['peak_mib'] / 1024:.1f} GiB, "
                  f"{per_point:.0f} bytes per point: at that rate {memory / 2 ** 30:.0f} GiB of memory hold about "
                  f"{memory / per_point / 1e6:.0f} million points."]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {out}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sizes", default="10000,100000,1000000,5000000")
    parser.add_argument("--shapes", default="sphere,torus,cube")
    parser.add_argument("--largest", type=int, default=10000000)
    parser.add_argument("--timeout", type=int, default=900)
    parser.add_argument("--name", default="scaling", help="bench/NAME.json, .md and plots/NAME.png")
    parser.add_argument("--report-only", action="store_true", help="rewrite the report from bench/scaling.json")
    args = parser.parse_args()
    args.sizes = [int(s) for s in args.sizes.split(",") if s]
    args.shapes = [s for s in args.shapes.split(",") if s]
    rows = compare.saved_or_measured(os.path.join(HERE, args.name + ".json"), args.report_only, lambda: run(args))
    report(rows, args.name)


if __name__ == "__main__":
    main()

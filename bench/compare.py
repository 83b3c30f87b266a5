#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""pcl_wrap against the triangulation floor and every peer, on the same points in one run.

usage: bench/compare.py [--sizes 10000,100000,1000000] [--large 5000000] [--large-shapes LIST]
                        [--large-peers LIST] [--timeout 900] [--all-shapes-up-to N]
                        [--small-runs 3] [--small-up-to 20000] [--warm-memory] [--smoke] [--out BENCHMARK.md]

For each dataset (sphere, torus, cube at each size; kitten, bunny, fandisk from libcgal-demo),
runs every method in a process of its own (bench_peers, open3d_peer.py), then mesh_quality on
its output, and writes the Markdown report with plots. Sizes in --large run the shapes in
--large-shapes (all by default) with the floor, pcl_wrap and only the peers in --large-peers (by
default the two fastest at a million points; the others take many minutes per run there). Needs
the build's bench/ (PCL_WRAP_BENCH_DIR, default build/bench) and the data (scripts/fetch-data.sh)."""
import argparse
import json
import mmap
import os
import platform
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
BENCH = os.environ.get("PCL_WRAP_BENCH_DIR", os.path.join(ROOT, "build", "bench"))
C_METHODS = ["floor_delaunay", "floor_regular", "pcl_wrap", "pcl_wrap_front", "cgal_advancing_front", "cgal_alpha_wrap",
             "cgal_alpha_shape", "pcl_concave_hull", "pcl_greedy_projection"]
PY_METHODS = ["open3d_ball_pivoting", "open3d_alpha_shape"]
FLOOR = {"floor_delaunay", "floor_regular"}
DEFAULT_LARGE_PEERS = ["cgal_alpha_wrap", "cgal_advancing_front"]
SHAPES = ["sphere", "torus", "cube"]
LABEL = {"floor_delaunay": "CGAL Delaunay_triangulation_3 (floor)",
         "floor_regular": "CGAL Regular_triangulation_3 (floor)", "pcl_wrap": "**pcl_wrap**",
         "pcl_wrap_front": "**pcl_wrap** --radius-rel 4",
         "cgal_advancing_front": "CGAL Advancing Front", "cgal_alpha_wrap": "CGAL Alpha_wrap_3",
         "cgal_alpha_shape": "CGAL Alpha_shape_3 (optimal alpha)", "pcl_concave_hull": "PCL ConcaveHull",
         "pcl_greedy_projection": "PCL GreedyProjection", "open3d_ball_pivoting": "Open3D ball pivoting",
         "open3d_alpha_shape": "Open3D alpha shape"}


def warm_memory(size):
    """Writes to every page of size bytes of fresh memory, then frees it. This VM reports freed
    memory to its host, and the first touch of a reported page waits for the host (0.5-2 s per
    GB); warmed, a method's run starts from recently freed pages whatever ran before it, as on a
    machine without such reporting (see warmMemory() in bench_wrap.cpp). In a child process:
    the methods' processes inherit this one's peak resident size, and would report it as theirs."""
    child = os.fork()
    if child:
        os.waitpid(child, 0)
        return
    try:
        m = mmap.mmap(-1, size)
        if hasattr(m, "madvise") and hasattr(mmap, "MADV_HUGEPAGE"):
            m.madvise(mmap.MADV_HUGEPAGE)
        for i in range(0, size, 4096):
            m[i] = 1
    finally:
        os._exit(0)


def available_memory():
    with open("/proc/meminfo") as f:
        return next(int(l.split()[1]) * 1024 for l in f if l.startswith("MemAvailable"))


def run_method(method, source, n, work, timeout, quality=True):
    """One method on one dataset: its JSON line plus quality (unless told not to), or an error."""
    mesh = os.path.join(work, "".join(c if c.isalnum() or c == "_" else "-" for c in method) + ".obj")
    points_xyz = os.path.join(work, "points.xyz")
    if method in PY_METHODS:
        cmd = ["/usr/bin/python3", os.path.join(HERE, "open3d_peer.py"), method, points_xyz, "--mesh", mesh]
    else:
        cmd = [os.path.join(BENCH, "bench_peers"), method, source, str(n), "1", "--mesh", mesh]
    try:
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"method": method, "error": f"over {timeout} s"}
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["exit %d" % done.returncode])[-1]
        return {"method": method, "error": "failed: " + last[:120]}
    result = json.loads(done.stdout.strip().splitlines()[-1])
    if quality and method not in FLOOR and result["triangles"] > 0 and os.path.exists(mesh):
        reference = DATASET_REFERENCE.get(source)
        spec = source if os.path.exists(source) else f"{source}:{n}:1"
        q = subprocess.run([os.path.join(BENCH, "mesh_quality"), mesh, spec, reference or "none",
                            "20000" if n <= 20000 else "200000"], capture_output=True, text=True, timeout=timeout)
        if q.returncode == 0:
            quality = json.loads(q.stdout.strip().splitlines()[-1])
            if reference is None:
                quality["chamfer"] = quality["hausdorff"] = None
            result.update(quality)
    if os.path.exists(mesh):
        os.remove(mesh)
    return result


DATASET_REFERENCE = {"sphere": "sphere", "torus": "torus"}


def datasets(args):
    data = os.path.join(ROOT, "data", "fetched")
    out = []
    # Every peer runs on --sizes; on --large sizes only the floor, pcl_wrap and --large-peers.
    synthetic = [(n, SHAPES, True) for n in args.sizes] + [(n, args.large_shapes, False) for n in args.large]
    for n, shapes, with_peers in synthetic:
        for shape in shapes:
            if shape == "sphere" or n <= args.all_shapes_up_to:
                out.append((f"{shape} {n:,}", shape, n, with_peers))
    if not args.smoke:
        for name, file, reference in (("kitten (scan)", "kitten.xyz", "points"),
                                      ("bunny (scan)", "bunny00.off", "bunny00.off"),
                                      ("fandisk (CAD)", "fandisk.off", "fandisk.off")):
            path = os.path.join(data, file)
            DATASET_REFERENCE[path] = path if reference != "points" else "points"
            out.append((name, path, 0, True))
    return out


def run_all(args):
    rows = []
    for name, source, n, with_peers in datasets(args):
        with tempfile.TemporaryDirectory() as work:
            # The points once, for the Python peers; the C++ ones rebuild the same from the seed.
            subprocess.run([os.path.join(BENCH, "bench_peers"), "floor_delaunay", source, str(n), "1", "--points",
                            os.path.join(work, "points.xyz")], check=True, capture_output=True)
            methods = [m for m in C_METHODS + PY_METHODS
                       if with_peers or m in FLOOR or m.startswith("pcl_wrap") or m in args.large_peers]
            with open(os.path.join(work, "points.xyz")) as f:
                count = sum(1 for _ in f)
            # Small inputs take milliseconds, which the machine's drift decides as much as the
            # method does: there every method runs in turns, each time in a fresh process, and
            # keeps its fastest run (quality is measured on the first).
            turns = args.small_runs if count <= args.small_up_to else 1
            # With --warm-memory each run is preceded by warming as much memory as the largest
            # peak so far on this dataset (at first about pcl_wrap's, scaled from a million
            # points), at most half the memory available.
            cap = available_memory() // 2
            warm = min(count * 1200, cap)
            best = {}
            for turn in range(turns):
                for method in methods:
                    if args.warm_memory:
                        warm_memory(warm)
                    result = run_method(method, source, n, work, args.timeout, quality=turn == 0)
                    if "peak_mib" in result:
                        warm = min(max(warm, int(result["peak_mib"] * 2 ** 20)), cap)
                    kept = best.setdefault(method, result)
                    if "error" not in result and "error" not in kept and result["seconds"] < kept["seconds"]:
                        for key in ("seconds", "normal_seconds", "peak_mib", "stages"):
                            if key in result:
                                kept[key] = result[key]
            for method in methods:
                best[method]["dataset"] = name
                best[method]["runs"] = turns
                rows.append(best[method])
                print(json.dumps(best[method]), flush=True)
    return rows


def saved_or_measured(saved, report_only, measure):
    """The rows kept in the JSON file saved when report_only, else measure()'s, kept there."""
    if report_only:
        with open(saved) as f:
            return json.load(f)
    rows = measure()
    with open(saved, "w") as f:
        json.dump(rows, f, indent=1)
    return rows


def regular_floor(rs):
    """Among one dataset's rows, the measured run of CGAL's regular triangulation, or None."""
    return next((r for r in rs if r["method"] == "floor_regular" and "seconds" in r), None)


def fmt(x, spec="{:.3g}"):
    return "-" if x is None else spec.format(x)


def this_machine():
    """The processor, cores and memory of the machine this runs on."""
    machine = f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores"
    try:
        with open("/proc/meminfo") as f:
            machine += f", {int(f.readline().split()[1]) // (1024 * 1024)} GiB"
        with open("/proc/cpuinfo") as f:
            model = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "")
        machine = f"{model}; " + machine
    except OSError:
        pass
    return machine


def report(rows, args, machine):
    lines = ["# Benchmarks", "",
             "pcl_wrap against the triangulation floor and the peers a user would pick instead, on the same",
             "points in one run, each method in a process of its own (time from points in memory to mesh in",
             "memory, normals included where a method needs them; peak resident memory of that process).",
             "This file is assembled by `bench/compare.py` from its measurements (`bench/results.json`) and the",
             "sections in `bench/*.md`, which other scripts write and readings are added to:",
             "`bench/compare.py --report-only` rewrites it from them, and a test checks that it is what they make.",
             "", f"Machine: {machine}. Reproduce: `scripts/build.sh && scripts/fetch-data.sh && bench/compare.py "
             f"--sizes {','.join(map(str, args.sizes))}" + (f" --large {','.join(map(str, args.large))}" if args.large else "")
             + (f" --large-shapes {','.join(args.large_shapes)}" if args.large and args.large_shapes != SHAPES else "")
             + (f" --large-peers {','.join(args.large_peers)}" if args.large and args.large_peers != DEFAULT_LARGE_PEERS else "")
             + (f" --all-shapes-up-to {args.all_shapes_up_to}" if args.all_shapes_up_to < 10 ** 9 else "")
             + f" --timeout {args.timeout}" + (f" --small-runs {args.small_runs}" if args.small_runs != 1 else "")
             + (f" --small-up-to {args.small_up_to}" if args.small_runs != 1 else "") + (" --warm-memory" if args.warm_memory else "") + "`.",
             "", "Before each run as much memory as the largest peak so far on the dataset was written and freed, so that no"
             " run waited on the VM's host for pages the process before it did not just free (`--warm-memory`)."
             if args.warm_memory else "Memory was not warmed before each run (see `--warm-memory`): a run's time includes"
             " the VM's host page faults for memory the process before it did not just free.",
             "", *(["Inputs of at most {:,} points: every method runs {} times in turns, each time in a process of".format(
                 args.small_up_to, args.small_runs),
                   "its own, and keeps its fastest run (their times are milliseconds, which the machine's drift",
                   "decides as much as the method does). Larger inputs: one run.", ""] if args.small_runs != 1 else []),
             *([f"Inputs of {', '.join(f'{n:,}' for n in args.large)} points ({', '.join(args.large_shapes)}): the floor, pcl_wrap and only "
                + (", ".join(LABEL[m] for m in args.large_peers) or "no peer")
                + (" (by default the two fastest peers at a million points; each of the others takes many minutes per run there)"
                   if args.large_peers == DEFAULT_LARGE_PEERS else "") + ".", ""]
               if args.large else []),
             "Quality: Chamfer (mean of both directions) and Hausdorff distance between the output and the",
             "reference surface (sphere, torus: analytic; bunny, fandisk: the reference mesh; kitten: the",
             "scan's points), sampled by area, relative to the bounding box diagonal; share of input points",
             "that are vertices of the output; watertight (every edge in exactly two triangles);",
             "non-manifold edges and vertices; components; genus (closed manifolds only).", ""]
    by_dataset = {}
    for r in rows:
        by_dataset.setdefault(r["dataset"], []).append(r)
    lines += against_the_floor(rows, by_dataset)
    lines += stages(by_dataset)
    for name, rs in by_dataset.items():
        floor = regular_floor(rs)
        lines += [f"## {name}", "",
                  "| method | time (s) | × floor | peak MiB | triangles | Chamfer | Hausdorff | points on output | watertight | non-manifold edges / vertices | components | genus |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in rs:
            if "error" in r:
                lines.append(f"| {LABEL[r['method']]} | {r['error']} | | | | | | | | | | |")
                continue
            ratio = r["seconds"] / floor["seconds"] if floor else None
            t = fmt(r["seconds"]) + (f" (normals {fmt(r['normal_seconds'])})" if r.get("normal_seconds") else "")
            if r["method"] in FLOOR:
                lines.append(f"| {LABEL[r['method']]} | {t} | {fmt(ratio, '{:.2f}')} | {r['peak_mib']:.0f} | | | | | | | | |")
                continue
            lines.append("| {} | {} | {} | {:.0f} | {} | {} | {} | {} | {} | {} | {} | {} |".format(
                LABEL[r["method"]], t, fmt(ratio, "{:.2f}"), r["peak_mib"], r["triangles"], fmt(r.get("chamfer")),
                fmt(r.get("hausdorff")), fmt(r.get("points_on_output"), "{:.1%}"),
                "yes" if r.get("watertight") else "no", f"{r.get('nonmanifold_edges', '-')} / {r.get('nonmanifold_vertices', '-')}",
                r.get("components", "-"), fmt(r.get("genus"), "{}")))
        lines.append("")
    return lines


def against_the_floor(rows, by_dataset):
    """Read off the rows: ratios to the floor (CGAL's regular triangulation) on the spheres,
    growth per point, and whether pcl_wrap is the fastest surface on each dataset."""
    ok = lambda r: "seconds" in r
    spheres = sorted({r["points"] for r in rows if r["dataset"].startswith("sphere ") and r["method"] == "pcl_wrap" and ok(r)})
    lines = ["## Against the floor", ""]
    if spheres:
        lines += ["| sphere points | pcl_wrap (s) | regular triangulation (s) | time ratio | memory ratio | µs per point |",
                  "|---|---|---|---|---|---|"]
        for n in spheres:
            rs = [r for r in rows if ok(r) and r["dataset"].startswith("sphere ") and r["points"] == n]
            w = next(r for r in rs if r["method"] == "pcl_wrap")
            f = regular_floor(rs)
            if f:
                lines.append(f"| {n:,} | {w['seconds']:.3g} | {f['seconds']:.3g} | {w['seconds'] / f['seconds']:.2f} "
                             f"| {w['peak_mib'] / f['peak_mib']:.2f} | {1e6 * w['seconds'] / n:.1f} |")
        lines.append("")
    faster = []
    for name, rs in by_dataset.items():
        w = next((r for r in rs if r["method"] == "pcl_wrap" and ok(r)), None)
        peers = [r for r in rs if r["method"] not in FLOOR and not r["method"].startswith("pcl_wrap") and ok(r)]
        if w and peers:
            beaten = [LABEL[r["method"]] for r in peers if r["seconds"] < w["seconds"]]
            faster.append(f"| {name} | {'yes' if not beaten else 'no: ' + ', '.join(beaten)} |")
    if faster:
        lines += ["| dataset | pcl_wrap faster than every peer? |", "|---|---|"] + faster + [""]
    return lines


def stages(by_dataset):
    """pcl_wrap's stage times on each dataset (from the run whose total is reported)."""
    runs = [(name, r) for name, rs in by_dataset.items() for r in rs if r["method"] == "pcl_wrap" and r.get("stages")]
    if not runs:
        return []
    names = []
    for _, r in runs:
        names += [s for s in r["stages"] if s not in names]
    lines = ["## pcl_wrap's stages", "",
             "Seconds per stage (triangulation: CGAL's, read into flat arrays and ordered; complex: every "
             "simplex named; classification: the exact predicates; collapse: the retraction; boundary: "
             "W = Bd X and the mesh).", "",
             "| dataset | " + " | ".join(names) + " | total | regular triangulation (floor) |",
             "|---|" + "---|" * (len(names) + 2)]
    for name, r in runs:
        floor = regular_floor(by_dataset[name])
        lines.append(f"| {name} | " + " | ".join(fmt(r["stages"].get(s)) for s in names)
                     + f" | {fmt(r['seconds'])} | {fmt(floor['seconds'] if floor else None)} |")
    return lines + [""]


def plot(rows, directory, draw=True):
    """The paths of the time plots, which are drawn unless draw is false."""
    paths = []
    for shape in ("sphere", "torus", "cube"):
        series = {}
        for r in rows:
            if r["dataset"].startswith(shape + " ") and "seconds" in r:
                series.setdefault(r["method"], []).append((r["points"], r["seconds"]))
        if not series:
            continue
        path = os.path.join(directory, f"time_{shape}.png")
        paths.append(path)
        if not draw:
            continue
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for method, pts in series.items():
            pts.sort()
            style = "-o" if method.startswith("pcl_wrap") else ("--" if method in FLOOR else ":.")
            ax.plot([p[0] for p in pts], [p[1] for p in pts], style, label=LABEL[method].replace("**", ""),
                    linewidth=2.5 if method.startswith("pcl_wrap") else 1.2)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("points")
        ax.set_ylabel("seconds")
        ax.set_title(f"{shape}: time against number of points")
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        plt.close(fig)
    return paths


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sizes", default="10000,100000,1000000")
    parser.add_argument("--large", default="")
    parser.add_argument("--large-shapes", default=",".join(SHAPES),
                        help="the synthetic shapes that run on --large sizes (comma-separated)")
    parser.add_argument("--large-peers", default=",".join(DEFAULT_LARGE_PEERS),
                        help="the peers that run on --large sizes (comma-separated method names)")
    parser.add_argument("--timeout", type=int, default=900)
    parser.add_argument("--all-shapes-up-to", type=int, default=10 ** 9,
                        help="larger sizes run on the sphere only")
    parser.add_argument("--smoke", action="store_true", help="a 500-point sphere, every method: checks the harness")
    parser.add_argument("--out", default=os.path.join(ROOT, "BENCHMARK.md"))
    parser.add_argument("--report-only", action="store_true", help="rewrite the report from bench/results.json")
    parser.add_argument("--check", action="store_true",
                        help="fail unless the report is what --report-only writes (no file written)")
    parser.add_argument("--small-runs", type=int, default=3, help="runs per method on small inputs, the fastest kept")
    parser.add_argument("--small-up-to", type=int, default=20000, help="the largest input that counts as small")
    parser.add_argument("--warm-memory", action="store_true",
                        help="before each run, write and free as much memory as the largest peak so far (see warm_memory)")
    args = parser.parse_args()
    args.sizes = [500] if args.smoke else [int(s) for s in args.sizes.split(",") if s]
    args.large = [] if args.smoke else [int(s) for s in args.large.split(",") if s]
    args.large_shapes = [shape for shape in args.large_shapes.split(",") if shape]
    if any(shape not in SHAPES for shape in args.large_shapes):
        parser.error(f"--large-shapes: known shapes are {', '.join(SHAPES)}")
    args.large_peers = [m for m in args.large_peers.split(",") if m]
    unknown = [m for m in args.large_peers if m not in LABEL]
    if unknown:
        parser.error(f"--large-peers: unknown methods {unknown}; known: {', '.join(LABEL)}")
    # results.json keeps the machine the rows were measured on: a report rewritten elsewhere
    # (--report-only) names that one, not its own.
    if args.report_only or args.check:
        with open(os.path.join(HERE, "results.json")) as f:
            saved = json.load(f)
        rows, machine = (saved, "not recorded") if isinstance(saved, list) else (saved["rows"], saved["machine"])
        args.warm_memory = not isinstance(saved, list) and saved.get("warm_memory", False)
    else:
        rows, machine = run_all(args), this_machine()
    if args.smoke:
        bad = [r for r in rows if "error" in r or (r["method"] not in FLOOR and "chamfer" not in r)]
        if bad:
            sys.exit(f"compare.py --smoke: {bad}")
        print("compare.py --smoke: every method ran and was measured")
        return
    if not args.report_only and not args.check:
        with open(os.path.join(HERE, "results.json"), "w") as f:
            json.dump({"machine": machine, "warm_memory": args.warm_memory, "rows": rows}, f, indent=1)
    plots = plot(rows, os.path.join(ROOT, "bench", "plots"), draw=not args.check)
    lines = report(rows, args, machine)
    # Sections other scripts write: bench/surface_quality.sh's table with its reading, bench/race.py's
    # time against quality, bench/scaling.py's time and memory per point (closed shapes and single
    # layers), bench/single_layers.py's table. A written reading of a generated section NAME.md sits
    # in NAME.reading.md, so that rerunning the script keeps it.
    for section in ("surface_quality.md", "race.md"):
        path = os.path.join(HERE, section)
        if os.path.exists(path):
            at = lines.index("## Against the floor")
            lines[at:at] = open(path).read().rstrip().split("\n") + [""]
    lines += ["## Time against number of points", ""] + [f"![]({os.path.relpath(p, os.path.dirname(args.out))})" for p in plots]
    for section in ("scaling", "scaling_single_layers", "single_layers"):
        for path in (os.path.join(HERE, section + ".md"), os.path.join(HERE, section + ".reading.md")):
            if os.path.exists(path):
                lines += [""] + open(path).read().rstrip().split("\n")
    # Measured by hand: perf and stage timings; bench/mpi_scaling.py's runs with their reading.
    for section in ("where_the_time_goes.md", "mpi_scaling.md"):
        path = os.path.join(HERE, section)
        if os.path.exists(path):
            lines += ["", open(path).read().rstrip()]
    text = "\n".join(lines) + "\n"
    if args.check:
        with open(args.out) as f:
            written = f.read()
        if written != text:
            have, want = written.split("\n"), text.split("\n")
            line = next((i + 1 for i, (a, b) in enumerate(zip(have, want)) if a != b), min(len(have), len(want)) + 1)
            sys.exit(f"{args.out} differs from what bench/compare.py --report-only writes from bench/results.json and "
                     f"the sections in bench/, from line {line}: edit the section in bench/, then rerun --report-only")
        print(f"compare.py --check: {args.out} is what the sections in bench/ make")
        return
    with open(args.out, "w") as f:
        f.write(text)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()

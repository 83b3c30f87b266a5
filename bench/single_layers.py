#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Single layers as a user meets them: what the default surface makes of them.

usage: bench/single_layers.py WORK_DIR [--pictures data/pictures] [--out bench/single_layers.md]
                              [--cli build/apps/pcl_wrap]

Generates a smooth and a rough terrain, a terrain with noise of a spacing, one with a steep cliff, a
city tile (ground and boxes of buildings seen from above), a one-sided scan of a half sphere and a
depth image of a bumpy wall, runs `pcl_wrap` (default and --closed) on each, and prints a Markdown
table: 2-manifold (every edge on one or two triangles, every vertex one fan), open (some edge on one
triangle only), consistently oriented, duplicate triangles, pieces, holes (boundary loops besides
the longest of each piece), share of the points on the surface, points copied, which way it faces,
time. With --pictures DIR, draws the raw W and the default surface side by side, seen obliquely,
with pcl_viewer as DIR/single_layer_NAME.png. With --out, writes the table as a section of
BENCHMARK.md (bench/compare.py puts it there)."""
import argparse
import collections
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def terrain(n, rng, rough=False, noise=0.0):
    """With noise, Gaussian noise in z of that many mean spacings (half as many median ones)."""
    xy = rng.uniform(-1, 1, (n, 2))
    z = 0.2 * np.sin(3 * xy[:, 0]) * np.cos(2 * xy[:, 1])
    if rough:
        z += 0.02 * np.sin(40 * xy[:, 0]) * np.cos(37 * xy[:, 1]) + rng.normal(0, 0.2 * 2 / np.sqrt(n), n)
    if noise:
        z += rng.normal(0, noise * 2 / np.sqrt(n), n)
    return np.c_[xy, z]


def cliff(n, rng):
    """Low ground, a cliff 0.4 high at x = 0.2 leaning out by 0.05, high ground."""
    top = rng.uniform(-1, 1, (n, 2))
    z = np.where(top[:, 0] > 0.2, 0.4, 0.0) + 0.05 * np.sin(2 * top[:, 1])
    face_n = int(n * 0.4 * 2 / 4)  # the face's area at the ground's density
    s, y = rng.uniform(0, 1, face_n), rng.uniform(-1, 1, face_n)
    face = np.c_[0.2 - 0.05 * s, y, 0.4 * s + 0.05 * np.sin(2 * y)]
    return np.r_[np.c_[top, z], face]


def city(n, rng):
    """Ground and flat-roofed buildings seen from above: roofs, ground and the walls facing up-ish
    (an aerial scan sees the walls only at a slant: a few points on each). Buildings overlap, a later
    one's roof over an earlier one's; wall points inside a building, under its roof, are not seen."""
    boxes = [(-0.6, -0.6, 0.3, 0.4, 0.3), (0.1, -0.7, 0.6, -0.2, 0.5), (-0.5, 0.2, -0.1, 0.7, 0.2),
             (0.3, 0.2, 0.7, 0.6, 0.4)]

    def roof(xy):
        z = np.zeros(len(xy))
        for x0, y0, x1, y1, h in boxes:
            z[(xy[:, 0] > x0) & (xy[:, 0] < x1) & (xy[:, 1] > y0) & (xy[:, 1] < y1)] = h
        return z

    xy = rng.uniform(-1, 1, (n, 2))
    z = roof(xy)
    walls = []
    for x0, y0, x1, y1, h in boxes:
        m = int(n * 2 * ((x1 - x0) + (y1 - y0)) * h / 4 * 0.3)  # sparser than the ground
        t, s = rng.uniform(0, 1, m), rng.uniform(0, h, m)
        side = rng.integers(0, 4, m)
        x = np.where(side < 2, x0 + t * (x1 - x0), np.where(side == 2, x0, x1))
        y = np.where(side >= 2, y0 + t * (y1 - y0), np.where(side == 0, y0, y1))
        seen = s >= roof(np.c_[x, y])
        walls.append(np.c_[x, y, s][seen])
    return np.r_[np.c_[xy, z], np.concatenate(walls)]


def half_sphere(n, rng):
    v = rng.normal(size=(n, 3))
    v /= np.linalg.norm(v, axis=1)[:, None]
    v[:, 2] = np.abs(v[:, 2])
    return v


def depth_image(rng):
    """A 320 x 240 depth image of a bumpy wall 2 m away, as an organised .pcd would hold it (NaN
    where nothing came back); the wall faces the camera at the origin."""
    c, r = np.meshgrid(np.arange(320), np.arange(240))
    x, y = (c - 160) / 300.0, (r - 120) / 300.0
    depth = 2.0 + 0.05 * np.sin(8 * x) * np.cos(6 * y)
    p = np.c_[(x * depth).ravel(), (y * depth).ravel(), depth.ravel()]
    p[rng.uniform(size=len(p)) < 0.02] = np.nan
    return p


CASES = [
    ("terrain", lambda rng: terrain(50000, rng)),
    ("rough_terrain", lambda rng: terrain(50000, rng, rough=True)),
    ("noisy_terrain", lambda rng: terrain(50000, rng, noise=0.5)),
    ("cliff", lambda rng: cliff(50000, rng)),
    ("city_tile", lambda rng: city(60000, rng)),
    ("half_sphere", lambda rng: half_sphere(50000, rng)),
    ("depth_image", depth_image),
]


def read_obj(path):
    vertices, triangles = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices.append([float(t) for t in line.split()[1:4]])
            elif line.startswith("f "):
                triangles.append([int(t.split("/")[0]) - 1 for t in line.split()[1:4]])
    return np.array(vertices), np.array(triangles, dtype=np.int64).reshape(-1, 3)


def describe(vertices, triangles, n):
    uses = collections.Counter()
    directed = set()
    oriented = True
    for t in triangles:
        for k in range(3):
            a, b = int(t[k]), int(t[(k + 1) % 3])
            uses[(min(a, b), max(a, b))] += 1
            oriented &= (a, b) not in directed
            directed.add((a, b))
    edge_manifold = all(c <= 2 for c in uses.values())
    links = collections.defaultdict(list)
    for t in triangles:
        for k in range(3):
            links[int(t[k])].append((int(t[(k + 1) % 3]), int(t[(k + 2) % 3])))
    vertex_manifold = True
    for v, edges in links.items():
        parent = {}

        def find(x):
            while parent.setdefault(x, x) != x:
                x = parent[x]
            return x
        degree = collections.Counter()
        for a, b in edges:
            parent[find(a)] = find(b)
            degree[a] += 1
            degree[b] += 1
        roots = {find(x) for x in degree}
        vertex_manifold &= len(roots) == 1 and max(degree.values()) <= 2 and sum(d == 1 for d in degree.values()) <= 2
    # Pieces and boundary loops.
    parent = list(range(len(vertices)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    for a, b in uses:
        parent[find(a)] = find(b)
    pieces = {find(int(v)) for v in np.unique(triangles)}
    out = {a: b for a, b in directed if uses[(min(a, b), max(a, b))] == 1}
    loops, seen = collections.defaultdict(list), set()
    for start in out:
        if start in seen:
            continue
        length, v = 0, start
        while v not in seen and v in out:
            seen.add(v)
            v = out[v]
            length += 1
        loops[find(start)].append(length)
    holes = sum(len(ls) - 1 for ls in loops.values())
    duplicates = len(triangles) - len({tuple(sorted(t)) for t in triangles.tolist()})
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    normal = np.cross(b - a, c - a).sum(axis=0)
    return {"manifold": edge_manifold and vertex_manifold, "open": bool(out), "oriented": oriented,
            "duplicates": duplicates, "pieces": len(pieces), "holes": holes,
            "share": len(np.unique(triangles)) / n, "copied": len(vertices) - n, "normal": normal}


def facing(normal):
    axis = int(np.argmax(np.abs(normal)))
    return ("+" if normal[axis] > 0 else "-") + "xyz"[axis]


def tilted_obj(source, target):
    """The mesh with its vertices turned 55 degrees about x, then 25 about z: an oblique view from
    above; NaN vertices (unseen pixels) at the origin, where no triangle uses them."""
    vertices, triangles = read_obj(source)
    vertices = np.nan_to_num(vertices)
    a, b = np.radians(-55), np.radians(25)
    rx = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
    rz = np.array([[np.cos(b), -np.sin(b), 0], [np.sin(b), np.cos(b), 0], [0, 0, 1]])
    vertices = vertices @ (rz @ rx).T
    with open(target, "w") as f:
        f.writelines(f"v {x:.7g} {y:.7g} {z:.7g}\n" for x, y, z in vertices)
        f.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in triangles)


def picture(args, name, path):
    """The raw W and the default surface side by side, seen obliquely from above, drawn by
    pcl_viewer (scripts/view.sh), as DIR/single_layer_NAME.png."""
    shots = []
    for label, option in (("the paper's W", ["--raw"]), ("pcl_wrap", [])):
        mesh = os.path.join(args.work, "picture.obj")
        subprocess.run([args.cli, path, mesh, "--quiet"] + option, check=True)
        tilted_obj(mesh, os.path.join(args.work, "tilted.obj"))
        vtk = os.path.join(args.work, "tilted.vtk")
        subprocess.run(["pcl_obj2vtk", os.path.join(args.work, "tilted.obj"), vtk], check=True,
                       stdout=subprocess.DEVNULL)
        png = os.path.join(args.work, f"{name}_{len(shots)}.png")
        subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", os.path.join(ROOT, "scripts", "view.sh"),
                        vtk, png], check=True, stderr=subprocess.DEVNULL)
        shots.append(f"{png}:{label}")
    os.makedirs(args.pictures, exist_ok=True)
    subprocess.run([os.path.join(HERE, "side_by_side.py"), os.path.join(args.pictures, f"single_layer_{name}.png")]
                   + shots, check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("work")
    parser.add_argument("--pictures", metavar="DIR")
    parser.add_argument("--out")
    parser.add_argument("--cli", default=os.path.join(ROOT, "build", "apps", "pcl_wrap"))
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    rows = ["| cloud | points | output | 2-manifold | open | oriented | duplicate triangles | pieces | holes "
            "| points on it | points copied | faces | s |", "|---" * 13 + "|"]
    for name, make in CASES:
        points = make(np.random.default_rng(sum(map(ord, name))))
        path = os.path.join(args.work, name + ".xyz")
        np.savetxt(path, points[np.isfinite(points).all(axis=1)] if name != "depth_image" else points, fmt="%.7g")
        n = int(np.isfinite(points).all(axis=1).sum())
        for option in ([], ["--closed"]):
            mesh = os.path.join(args.work, name + ("_closed" if option else "") + ".obj")
            start = time.perf_counter()
            subprocess.run([args.cli, path, mesh, "--quiet"] + option, check=True)
            seconds = time.perf_counter() - start
            vertices, triangles = read_obj(mesh)
            # The output's vertices are the input's finite rows, in order, copies after them.
            d = describe(vertices, triangles, n)
            d["share"] = len(np.unique(triangles[triangles < n])) / n
            d["copied"] = len(vertices) - n
            rows.append(f"| {name} | {n:,} | {'closed' if option else 'default'} | "
                        f"{'yes' if d['manifold'] else 'no'} | {'yes' if d['open'] else 'no'} | "
                        f"{'yes' if d['oriented'] else 'no'} | "
                        f"{d['duplicates']} | {d['pieces']} | {d['holes'] if not option else '-'} | "
                        f"{100 * d['share']:.2f}% | {d['copied']:,} | {facing(d['normal']) if not option else '-'} | "
                        f"{seconds:.2f} |")
        if args.pictures:
            picture(args, name, path)
    print("\n".join(rows))
    if args.out:
        lines = ["## Single layers", "",
                 "Terrains (smooth, rough, with noise of a spacing), a cliff, a city tile seen from above, a",
                 "one-sided scan of a half sphere and a depth image: the default output (one open sheet) and",
                 "`--closed` (the two-sided shell), checked as a user would (bench/single_layers.py). Holes:",
                 "boundary loops besides each piece's outer one.",
                 "Faces: the axis of the summed area normal. Reproduce: `scripts/build.sh && bench/single_layers.py",
                 "/tmp/single_layers --pictures data/pictures --out bench/single_layers.md`.", ""] + rows
        if args.pictures:
            rel = os.path.relpath(args.pictures, ROOT)
            lines += ["", " ".join(f"![{name}]({rel}/single_layer_{name}.png)" for name, _ in CASES)]
        with open(args.out, "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.exit(main())

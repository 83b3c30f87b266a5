#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Runs the pcl_wrap tool on point files at several relative radii and prints a Markdown table:
genus, components, share of points on W, triangles, non-manifold edges, time.

usage: bench/deletion_table.py PCL_WRAP_BINARY FILE[:MODE] ... [--radius-rel K ...]
"""
import json
import os
import subprocess
import sys
import tempfile
from collections import defaultdict


def read_obj(path):
    vertices, triangles = 0, []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices += 1
            elif line.startswith("f "):
                triangles.append(tuple(int(t.split("/")[0]) - 1 for t in line.split()[1:]))
    return vertices, triangles


def describe(triangles):
    """Components, Euler characteristic, edges on other than two triangles, points used."""
    edges = defaultdict(int)
    used = set()
    for t in triangles:
        used.update(t)
        for i in range(3):
            a, b = t[i], t[(i + 1) % 3]
            edges[(min(a, b), max(a, b))] += 1
    parent = {v: v for v in used}

    def find(v):
        while parent[v] != v:
            parent[v] = parent[parent[v]]
            v = parent[v]
        return v

    for a, b in edges:
        parent[find(a)] = find(b)
    components = len({find(v) for v in used})
    euler = len(used) - len(edges) + len(triangles)
    odd = sum(1 for n in edges.values() if n != 2)
    return components, euler, odd, len(used)


def main():
    args = sys.argv[1:]
    binary, inputs, radii = args[0], [], []
    i = 1
    while i < len(args):
        if args[i] == "--radius-rel":
            radii.append(args[i + 1])
            i += 2
        else:
            inputs.append(args[i])
            i += 1
    radii = radii or ["basic", "8", "4", "3", "2"]
    print("| input | mode | radius-rel | genus | components | points on W | triangles | edges not in 2 triangles | sinks deleted | time (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for spec in inputs:
            path, _, mode = spec.partition(":")
            mode = mode or "front"
            for r in radii:
                out, stats = os.path.join(tmp, "w.obj"), os.path.join(tmp, "s.json")
                cmd = [binary, path, out, "--quiet", "--stats-json", stats]
                if r != "basic":
                    cmd += ["--radius-rel", r, "--mode", mode]
                subprocess.run(cmd, check=True)
                s = json.load(open(stats))
                n, triangles = read_obj(out)
                components, euler, odd, used = describe(triangles)
                # Closed orientable surfaces: genus g per component sums to (2 c - chi) / 2.
                genus = (2 * components - euler) // 2 if odd == 0 else "-"
                print(f"| {os.path.basename(path)} | {mode if r != 'basic' else '-'} | {r} | {genus} | {components} "
                      f"| {100.0 * used / s['points']['used']:.1f}% | {len(triangles)} | {odd} "
                      f"| {s['deletion']['deleted']} | {s['timings']['total']:.2f} |")


if __name__ == "__main__":
    main()

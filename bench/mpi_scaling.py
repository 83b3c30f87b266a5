#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: bench/mpi_scaling.py CLOUD [BUILD_DIR] [RANKS...] [--default]

Strong scaling of pcl_wrap_mpi on one machine: the raw W of CLOUD by one process (pcl_wrap --raw)
and by pcl_wrap_mpi on each number of RANKS (default 1 2 4; more ranks than cores run
oversubscribed, which shows the exchange rounds, not speed); with --default, the default surface
(both run without --raw). Prints a Markdown table: wall time, the slowest rank's stage times
(rank 0's for its surface stage), peak memory per rank, ghost share and exchange rounds, and
whether the output is the one process's (the default surface: the same file, byte for byte; W:
the same oriented triangles, which it lists in another order).
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import time


def off_triangles(path):
    """The oriented triangles of an .off file, each rotated to start at its smallest index."""
    with open(path) as f:
        assert f.readline().strip().endswith("OFF")
        line = f.readline()
        while line.startswith("#") or not line.strip():
            line = f.readline()
        nv, nf = (int(x) for x in line.split()[:2])
        for _ in range(nv):
            f.readline()
        out = set()
        for _ in range(nf):
            t = [int(x) for x in f.readline().split()[1:4]]
            k = t.index(min(t))
            out.add(tuple(t[k:] + t[:k]))
        return out


def run(command, env=None):
    start = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True, env=env)
    if done.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(command), done.stderr))
    return time.monotonic() - start, done.stdout, done.stderr


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    surface = "--default" in sys.argv[1:]
    args = [a for a in sys.argv[1:] if a != "--default"]
    raw = [] if surface else ["--raw"]
    cloud = args[0]
    build = args[1] if len(args) > 1 else "build"
    ranks = [int(k) for k in args[2:]] or [1, 2, 4]
    work = tempfile.mkdtemp(prefix="mpi_scaling_")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")

    single_off, single_json = os.path.join(work, "single.off"), os.path.join(work, "single.json")
    wall, _, err = run(["/usr/bin/time", "-f", "%M", os.path.join(build, "apps/pcl_wrap"), cloud, single_off] + raw +
                       ["--quiet", "--stats-json", single_json])
    peak = int(err.strip().splitlines()[-1]) / 1024
    stats = json.load(open(single_json))
    # The default surface is written as one process writes it; the raw W in another order.
    same_output = (lambda a, b: open(a, "rb").read() == open(b, "rb").read()) if surface else \
        (lambda a, b: off_triangles(a) == off_triangles(b))
    points = stats["points"]["input"]
    print("%s: %d points, %s %d triangles\n" % (os.path.basename(cloud), points, "default surface" if surface else "W",
                                                len(off_triangles(single_off))))
    print("| run | wall s | stages s (slowest rank) | peak MB per rank | ghosts | rounds (points, removals) | identical |")
    print("|---|---|---|---|---|---|---|")
    stages = lambda s: ", ".join("%s %.2f" % (k, v) for k, v in s["timings"].items() if k != "total")
    print("| pcl_wrap%s | %.1f | %s | %d | | | |" % ("" if surface else " --raw", wall, stages(stats), peak))
    for k in ranks:
        out_off, out_json = os.path.join(work, "mpi%d.off" % k), os.path.join(work, "mpi%d.json" % k)
        wall, out, _ = run(["mpirun", "--oversubscribe", "-np", str(k), os.path.join(build, "apps/mpi/pcl_wrap_mpi"),
                            cloud, out_off] + raw + ["--quiet", "--stats", "--stats-json", out_json], env)
        s = json.load(open(out_json))
        peaks = re.search(r"peak memory:\s+(.*) \(per rank\)", out).group(1).replace(" MB", "")
        tiles = re.search(r"ghosts (\d+) \(([\d.e+-]+)% of the points\), (\d+) rounds", out)
        removal_rounds = re.search(r"retraction:\s+(\d+) rounds", out).group(1)
        same = same_output(out_off, single_off)
        print("| pcl_wrap_mpi, %d rank%s | %.1f | %s | %s | %.1f%% | %s, %s | %s |" %
              (k, "" if k == 1 else "s", wall, stages(s), peaks, float(tiles.group(2)), tiles.group(3),
               removal_rounds, "yes" if same else "**no**"))


if __name__ == "__main__":
    main()

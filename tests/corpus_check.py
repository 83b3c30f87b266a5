#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: tests/corpus_check.py BUILD_DIR

The default surface on the quick corpus of bench/corpus.py (voids, parts cut away, holes, bridges,
separate objects, noise, resampled development meshes, outliers): each case must come out closed,
vertex-manifold, with the components and genus the case was made with and at least 99% of its
points on it (bench/corpus_table.py's test), except the cases in STILL_WRONG, which the default
surface does not get right yet (BENCHMARK.md shows them). One of those that comes out right is
reported, so that the list only shrinks. Uses BUILD_DIR/bench/bench_peers and mesh_quality.
"""
import json
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "bench"))
import corpus_table  # noqa: E402

STILL_WRONG = {
    "four_thin_cylinders",  # webs across gaps of 2-3 spacings at the caps
    "coupling_coarse",  # holes whose walls have about ten points around, plugged
    "chain_of_five_rings_coarse",  # tubes about seven points around, cut through
}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    build = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory() as work:
        cases_dir = os.path.join(work, "corpus")
        subprocess.run(["/usr/bin/python3", os.path.join(here, "..", "bench", "corpus.py"), cases_dir, "--quick"],
                       check=True)
        cases = json.load(open(os.path.join(cases_dir, "manifest.json")))
        wrong, now_right = [], []
        for case in cases:
            q = corpus_table.run(build, "pcl_wrap", os.path.join(cases_dir, case["name"] + ".xyz"), work)
            ok = corpus_table.right(q, case, "pcl_wrap")
            got = corpus_table.described(q)
            print("%-32s expected c%d g%d, got %s%s" % (case["name"], case["components"], case["genus"], got,
                                                      "" if ok else "  WRONG"))
            if not ok and case["name"] not in STILL_WRONG:
                wrong.append(case["name"])
            if ok and case["name"] in STILL_WRONG:
                now_right.append(case["name"])
        if len(cases) < 30:
            sys.exit("only %d cases: is libcgal-demo installed (scripts/setup.sh)?" % len(cases))
        if now_right:
            print("now right, to take off STILL_WRONG: " + ", ".join(now_right))
        if wrong:
            sys.exit("wrong: " + ", ".join(wrong))


if __name__ == "__main__":
    main()

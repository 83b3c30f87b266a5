# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python package against the command-line tool, bad input, threads and Open3D.

Run by ctest with PYTHONPATH=build/python and PCL_WRAP_CLI, PCL_WRAP_DATA_DIR and
PCL_WRAP_EXAMPLE set; with Debian's /usr/bin/python3 (numpy, open3d).
"""
import json
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np

import pcl_wrap
from pcl_wrap import Region, Threshold

CLI = os.environ.get("PCL_WRAP_CLI", "")
DATA = os.environ.get("PCL_WRAP_DATA_DIR", "")
EXAMPLE = os.environ.get("PCL_WRAP_EXAMPLE", "")


def read_off_points(path):
    numbers = []
    with open(path) as f:
        tokens = [line.split() for line in f if line.strip() and not line.lstrip().startswith("#")]
    n = int(tokens[1][0])
    for row in tokens[2:2 + n]:
        numbers.append([float(v) for v in row[:3]])
    return np.array(numbers)


def read_obj_triangles(path):
    with open(path) as f:
        faces = [[int(v.split("/")[0]) - 1 for v in line.split()[1:]] for line in f if line.startswith("f ")]
    return np.array(faces, dtype=np.int64).reshape(-1, 3)


def sphere(n, seed=1):
    p = np.random.default_rng(seed).normal(size=(n, 3))
    return p / np.linalg.norm(p, axis=1)[:, None]


def torus(n, seed=2, R=1.0, r=0.35):
    u, v = np.random.default_rng(seed).uniform(0, 2 * np.pi, size=(2, n))
    return np.stack([(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)], axis=1)


def edge_counts(triangles):
    """Directed edges of the triangles: a closed oriented surface has each once, and its reverse once."""
    edges = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    directed = {tuple(e) for e in edges}
    return len(edges), len(directed), all((b, a) in directed for a, b in directed)


class AgainstTheCommandLineTool(unittest.TestCase):
    @unittest.skipUnless(CLI and DATA, "needs PCL_WRAP_CLI and PCL_WRAP_DATA_DIR")
    def test_same_triangles_as_the_cli_on_the_bunny(self):
        bunny = os.path.join(DATA, "bunny00.off")
        points = read_off_points(bunny)
        with tempfile.TemporaryDirectory() as work:
            for mode, cli_options, options in (("surface", [], {}), ("raw", ["--raw"], {"output": "raw"})):
                mesh = os.path.join(work, mode + ".obj")
                subprocess.run([CLI, bunny, mesh, "--quiet"] + cli_options, check=True)
                expected = read_obj_triangles(mesh)
                result = pcl_wrap.wrap(points, **options)
                self.assertGreater(len(expected), 70000, mode)
                np.testing.assert_array_equal(result.triangles, expected, err_msg=mode)
        self.assertEqual(len(result.vertices), len(points) + len(result.copies))


class Input(unittest.TestCase):
    def test_float32_and_fortran_order_as_float64_c_order(self):
        points = sphere(3000).astype(np.float32)
        reference = pcl_wrap.wrap(points.astype(np.float64))
        self.assertEqual(len(reference.triangles), 2 * 3000 - 4)
        for variant in (points, np.asfortranarray(points), np.asfortranarray(points.astype(np.float64))):
            np.testing.assert_array_equal(pcl_wrap.wrap(variant).triangles, reference.triangles)
        np.testing.assert_array_equal(reference.vertices, points.astype(np.float64))

    def test_nan_rows_are_skipped_and_reported(self):
        points = sphere(2000)
        holes = [0, 17, 999, 2000]
        with_nans = np.insert(points, [0, 17 - 1, 999 - 2, 2000 - 3], np.nan, axis=0)
        with_nans[17, 1] = np.inf  # an infinite coordinate is skipped too
        self.assertTrue(all(not np.isfinite(with_nans[h]).all() for h in holes))
        result = pcl_wrap.wrap(with_nans)
        np.testing.assert_array_equal(result.skipped, holes)
        self.assertEqual(result.statistics["points"]["skipped"], len(holes))
        kept = np.delete(np.arange(len(with_nans)), holes)
        clean = pcl_wrap.wrap(points)
        np.testing.assert_array_equal(result.triangles, kept[clean.triangles])
        self.assertFalse(np.isin(result.triangles, holes).any())

    def test_weights_hide_a_point_with_an_empty_power_cell(self):
        points = np.concatenate([sphere(500), [[0.0, 0.0, 0.0]]])
        weights = np.zeros(len(points))
        weights[-1] = -10.0
        result = pcl_wrap.wrap(points, weights)
        np.testing.assert_array_equal(result.hidden, [len(points) - 1])
        np.testing.assert_array_equal(pcl_wrap.wrap(points, weights.astype(np.float32)).hidden, [len(points) - 1])

    def test_points_inside_a_volume_are_reported_off_the_surface(self):
        points = np.random.default_rng(3).uniform(-1, 1, (2000, 3))
        points[1500] = np.nan
        result = pcl_wrap.wrap(points)
        source = np.concatenate([np.arange(len(points)), result.copies]).astype(np.int64)
        on = np.unique(source[result.triangles])  # a copy counts as its point
        self.assertGreater(len(result.off_surface), 300)  # the inside of a cube
        self.assertEqual(result.statistics["points"]["off_surface"], len(result.off_surface))
        # Each row: on the surface, off it or skipped, and only one of them.
        every = np.concatenate([on, result.off_surface, result.skipped])
        np.testing.assert_array_equal(np.sort(every), np.arange(len(points)))

    def test_a_non_finite_weight_skips_its_point(self):
        points = sphere(300)
        weights = np.zeros(300)
        weights[[5, 77]] = np.nan, np.inf
        result = pcl_wrap.wrap(points, weights)
        np.testing.assert_array_equal(result.skipped, [5, 77])
        self.assertEqual(result.statistics["points"]["skipped"], 2)
        clean = pcl_wrap.wrap(np.delete(points, [5, 77], axis=0))
        self.assertEqual(len(result.triangles), len(clean.triangles))

    def test_enums_and_names_alike(self):
        points = torus(1500)
        for output in ("raw", pcl_wrap.Output.raw):
            for deletion in ("global", pcl_wrap.SinkDeletion.global_):
                result = pcl_wrap.wrap(points, output=output, deletion=deletion,
                                       threshold=Threshold.relative_radius(4))
                np.testing.assert_array_equal(result.triangles, pcl_wrap.wrap(
                    points, output="raw", deletion="global", threshold=Threshold.relative_radius(4)).triangles)

    def test_version_and_statistics_keys_as_the_cli(self):
        self.assertRegex(pcl_wrap.__version__, r"^\d+\.\d+\.\d+$")
        result = pcl_wrap.wrap(sphere(500))
        self.assertGreater(result.statistics["spacing"], 0)  # always, threshold or not
        self.assertAlmostEqual(result.statistics["spacing"], pcl_wrap.median_spacing(sphere(500)))
        if CLI:
            with tempfile.TemporaryDirectory() as work:
                source = os.path.join(work, "sphere.xyz")
                np.savetxt(source, sphere(500))
                stats = os.path.join(work, "stats.json")
                subprocess.run([CLI, source, os.path.join(work, "out.ply"), "--quiet", "--stats-json", stats], check=True)
                with open(stats) as f:
                    cli = json.load(f)
            self.assertEqual(set(cli), set(result.statistics))
            for group in ("points", "deletion", "manifold", "w"):
                self.assertEqual(set(cli[group]), set(result.statistics[group]), group)
            self.assertEqual(cli["spacing"], result.statistics["spacing"])

    def test_empty_and_tiny_inputs(self):
        for n in range(4):
            result = pcl_wrap.wrap(sphere(4)[:n].reshape(n, 3))
            self.assertEqual(result.triangles.shape, (0, 3))
            self.assertEqual(len(result.vertices), n)
        tetrahedron = pcl_wrap.wrap([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
        self.assertEqual(len(tetrahedron.triangles), 4)
        self.assertEqual(tetrahedron.triangles.dtype, np.int64)

    def test_bad_input_raises_value_error(self):
        points = sphere(200)
        bad = [
            (lambda: pcl_wrap.wrap(points[:, :2]), "(n, 3)"),
            (lambda: pcl_wrap.wrap(points[:, :, None]), "(n, 3)"),
            (lambda: pcl_wrap.wrap(points.ravel()), "(n, 3)"),
            (lambda: pcl_wrap.wrap([["a", "b", "c"]]), "real numbers"),
            (lambda: pcl_wrap.wrap(points.astype(complex)), "real numbers"),
            (lambda: pcl_wrap.wrap(points, np.zeros(199)), "one per point"),
            (lambda: pcl_wrap.wrap(points, colors=np.zeros((199, 3))), "colors must be (200, 3)"),
            (lambda: pcl_wrap.wrap(points, normals=np.zeros(200)), "normals must be (200, 3)"),
            (lambda: pcl_wrap.wrap(points, threshold=4), "Threshold"),
            (lambda: pcl_wrap.wrap(points, threshold=Threshold.relative_radius(0)), "relative radius"),
            (lambda: pcl_wrap.wrap(points, threshold=Threshold.largest(0)), "count"),
            (lambda: pcl_wrap.wrap(points, output="manifold"), "output"),
            (lambda: pcl_wrap.wrap(points, deletion="local"), "deletion"),
            (lambda: pcl_wrap.wrap(points, manifold="yes"), "manifold"),
            (lambda: pcl_wrap.wrap(points, manifold=True), "output='raw'"),
            (lambda: pcl_wrap.wrap(points, num_threads=-1), "num_threads"),
            (lambda: pcl_wrap.wrap(points, weight_scale=float("nan")), "weight_scale"),
            (lambda: pcl_wrap.wrap(points, region=Region.sphere(0, 0, 0, 1)), "region"),
            (lambda: pcl_wrap.wrap(points, region=Region.sphere(0, 0, 0, -1),
                                   threshold=Threshold.relative_radius(4)), "radius"),
            (lambda: pcl_wrap.wrap(points, region=(0, 0, 0, 1)), "Region"),
        ]
        for call, message in bad:
            with self.assertRaises(ValueError) as raised:
                call()
            self.assertIn(message, str(raised.exception))
        with self.assertRaises(TypeError):  # every option is a named keyword
            pcl_wrap.wrap(points, radius_rel=4)
        self.assertEqual(len(pcl_wrap.wrap(points).triangles), 2 * 200 - 4)  # still works


class Options(unittest.TestCase):
    def test_threads_do_not_change_the_triangles(self):
        points = torus(5000)
        one = pcl_wrap.wrap(points, num_threads=1)
        np.testing.assert_array_equal(pcl_wrap.wrap(points, num_threads=2).triangles, one.triangles)
        np.testing.assert_array_equal(pcl_wrap.wrap(points).triangles, one.triangles)
        self.assertIn("triangulation", one.statistics["timings"])
        self.assertGreater(one.statistics["timings"]["total"], 0)

    def test_default_surface_is_a_closed_oriented_torus_through_every_point(self):
        points = torus(5000)
        result = pcl_wrap.wrap(points)
        edges, directed, paired = edge_counts(result.triangles)
        self.assertEqual(edges, directed)
        self.assertTrue(paired)
        self.assertEqual(len(np.unique(result.triangles)), len(result.vertices))
        euler = len(result.vertices) - edges // 2 + len(result.triangles)
        self.assertEqual(euler, 0)  # genus 1
        raw = pcl_wrap.wrap(points, output="raw")
        self.assertFalse(np.array_equal(raw.triangles, result.triangles))

    def test_a_terrain_is_one_open_sheet_facing_up_or_the_viewpoint(self):
        rng = np.random.default_rng(3)
        xy = rng.uniform(-1, 1, (4000, 2))
        points = np.c_[xy, 0.2 * np.sin(3 * xy[:, 0]) * np.cos(2 * xy[:, 1])]
        result = pcl_wrap.wrap(points)
        self.assertTrue(result.statistics["manifold"]["single_layer"])
        self.assertEqual(len(result.vertices), len(points))  # no point copied
        edges, directed, paired = edge_counts(result.triangles)
        self.assertEqual(edges, directed)  # every directed edge once: oriented
        self.assertFalse(paired)  # open: some edge on one triangle only
        a, b, c = (result.vertices[result.triangles[:, k]] for k in range(3))
        up = np.cross(b - a, c - a)[:, 2].sum()
        self.assertGreater(up, 0)
        below = pcl_wrap.wrap(points, viewpoint=(0, 0, -10))
        a, b, c = (below.vertices[below.triangles[:, k]] for k in range(3))
        self.assertLess(np.cross(b - a, c - a)[:, 2].sum(), 0)
        closed = pcl_wrap.wrap(points, output="closed")
        edges, directed, paired = edge_counts(closed.triangles)
        self.assertTrue(paired)
        self.assertGreater(len(closed.vertices), len(points))  # copies per side
        with self.assertRaises(ValueError):
            pcl_wrap.wrap(points, viewpoint=(0, float("nan"), 0))

    def test_threshold_region_and_complex(self):
        points = torus(4000)
        basic = pcl_wrap.wrap(points, output="raw", keep_complex=True)
        tight = pcl_wrap.wrap(points, output="raw", threshold=Threshold.relative_radius(4))
        self.assertGreater(tight.statistics["deletion"]["deleted"], 0)
        self.assertNotEqual(len(tight.triangles), len(basic.triangles))
        self.assertAlmostEqual(tight.statistics["spacing"], pcl_wrap.median_spacing(points))
        everywhere = pcl_wrap.wrap(points, output="raw", threshold=Threshold.relative_radius(4),
                                   region=Region.box(-2, -2, -2, 2, 2, 2))
        np.testing.assert_array_equal(everywhere.triangles, tight.triangles)
        elsewhere = pcl_wrap.wrap(points, output="raw", threshold=Threshold.relative_radius(4),
                                  region=Region.sphere(10, 10, 10, 1))
        self.assertEqual(elsewhere.statistics["deletion"]["deleted"], 0)
        np.testing.assert_array_equal(elsewhere.triangles, basic.triangles)
        self.assertIsNone(tight.complex)
        for k, simplices in enumerate(basic.complex):
            self.assertEqual(simplices["vertices"].shape[1], k + 1)
            counts = np.bincount(simplices["classes"], minlength=3)
            stats = basic.statistics["simplices"][str(k)]
            self.assertEqual(list(counts), [stats[c] for c in pcl_wrap.SIMPLEX_CLASSES])
            self.assertEqual(int(simplices["in_x"].sum()), basic.statistics["x_simplices"][str(k)])

    def test_w_is_the_papers_whatever_the_output(self):
        points = torus(2000)
        raw = pcl_wrap.wrap(points, output="raw", keep_complex=True)
        default = pcl_wrap.wrap(points, keep_complex=True)
        self.assertIsNone(pcl_wrap.wrap(points).w)
        np.testing.assert_array_equal(raw.w["triangles"], raw.triangles)
        self.assertEqual({tuple(t) for t in default.w["triangles"]}, {tuple(t) for t in raw.triangles})
        self.assertNotEqual({tuple(t) for t in default.triangles}, {tuple(t) for t in raw.triangles})

    def test_filtration_gives_the_basic_and_a_tighter_wrap(self):
        points = torus(3000)
        result = pcl_wrap.wrap(points, output="raw", filtration=True)
        basic = result.filtration.surface(float("inf"))["triangles"]
        self.assertEqual({tuple(sorted(t)) for t in basic}, {tuple(sorted(t)) for t in result.triangles})
        sizes = result.filtration.sink_sizes
        self.assertTrue(np.all(np.diff(sizes) <= 0))
        self.assertLess(result.filtration.x_size(sizes[len(sizes) // 2])[3],
                        result.filtration.x_size(float("inf"))[3])


class Interpreter(unittest.TestCase):
    def test_the_gil_is_released_while_computing(self):
        points = sphere(150000)
        span = {}

        def compute():
            span["start"] = time.perf_counter()
            pcl_wrap.wrap(points, output="raw", num_threads=1)
            span["end"] = time.perf_counter()

        worker = threading.Thread(target=compute)
        stamps = []
        worker.start()
        while worker.is_alive():
            stamps.append(time.perf_counter())
        worker.join()
        inside = [t for t in stamps if span["start"] < t < span["end"]]
        length = span["end"] - span["start"]
        self.assertGreater(length, 0.2)
        # Holding the GIL, the call would leave this thread at most one switch interval (5 ms).
        self.assertTrue(inside)
        self.assertGreater(max(inside) - min(inside), 0.8 * length)


    def test_a_forked_child_computes_on_more_than_one_thread(self):
        if (os.cpu_count() or 1) < 2:
            self.skipTest("one core: no worker threads")
        points = sphere(20000)
        pcl_wrap.wrap(points)  # the worker threads start in this process
        read, write = os.pipe()
        child = os.fork()
        if child == 0:
            try:
                pcl_wrap.wrap(points, output="raw")
                os.write(write, str(len(os.listdir("/proc/self/task"))).encode())
            finally:
                os._exit(0)
        os.close(write)
        with os.fdopen(read) as answer:
            threads = int(answer.read() or "0")
        os.waitpid(child, 0)
        # Forked while the workers lived, the child would have inherited none, believed it had
        # them, and kept its one thread.
        self.assertGreater(threads, 1)

    def test_ctrl_c_ends_the_computation_between_stages(self):
        script = ("import numpy as np, pcl_wrap, sys\n"
                  "p = np.random.default_rng(1).uniform(-1, 1, size=(1000000, 3))\n"
                  "print('start', flush=True)\n"
                  "try:\n"
                  "    pcl_wrap.wrap(p)\n"
                  "except KeyboardInterrupt:\n"
                  "    print('interrupted', flush=True)\n"
                  "    sys.exit(3)\n")
        child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
        self.assertEqual(child.stdout.readline().strip(), "start")
        time.sleep(1.0)
        start = time.perf_counter()
        child.send_signal(signal.SIGINT)
        out, _ = child.communicate(timeout=120)
        self.assertEqual(child.returncode, 3, out)
        self.assertIn("interrupted", out)
        # It stops within the triangulation, not after the whole construction (10 s and more).
        self.assertLess(time.perf_counter() - start, 4.0)


class Open3D(unittest.TestCase):
    def setUp(self):
        try:
            import open3d  # noqa: F401
        except ImportError:
            self.skipTest("Open3D is not installed")

    def test_round_trip_through_open3d(self):
        import open3d as o3d
        points = torus(4000)
        points[10] = np.nan
        result = pcl_wrap.wrap(points)
        mesh = pcl_wrap.to_open3d(result)
        self.assertIsInstance(mesh, o3d.geometry.TriangleMesh)
        # The skipped row is left out: no NaN vertex, the rows after it one place earlier.
        self.assertTrue(np.isfinite(np.asarray(mesh.get_center())).all())
        np.testing.assert_array_equal(np.asarray(mesh.vertices), np.delete(result.vertices, 10, axis=0))
        renumbered = np.where(result.triangles > 10, result.triangles - 1, result.triangles)
        np.testing.assert_array_equal(np.asarray(mesh.triangles), renumbered)
        self.assertTrue(mesh.is_edge_manifold(allow_boundary_edges=False))  # closed
        self.assertTrue(mesh.is_vertex_manifold())
        self.assertTrue(mesh.is_orientable())
        with tempfile.TemporaryDirectory() as work:
            path = os.path.join(work, "torus.ply")
            self.assertTrue(o3d.io.write_triangle_mesh(path, mesh))
            back = o3d.io.read_triangle_mesh(path)
        np.testing.assert_array_equal(np.asarray(back.triangles), np.asarray(mesh.triangles))
        np.testing.assert_allclose(np.asarray(back.vertices), np.asarray(mesh.vertices))

    def test_colours_and_normals_of_an_open3d_cloud_reach_the_mesh(self):
        import open3d as o3d
        points = torus(3000)
        cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
        colours = (points - points.min(axis=0)) / np.ptp(points, axis=0)
        cloud.colors = o3d.utility.Vector3dVector(colours)
        cloud.estimate_normals()
        result = pcl_wrap.wrap(cloud)
        np.testing.assert_array_equal(result.triangles, pcl_wrap.wrap(points).triangles)
        np.testing.assert_allclose(result.colors[:3000], colours)
        np.testing.assert_allclose(result.normals[:3000], np.asarray(cloud.normals))
        mesh = pcl_wrap.to_open3d(result)
        self.assertTrue(mesh.has_vertex_colors() and mesh.has_vertex_normals())
        np.testing.assert_allclose(np.asarray(mesh.vertex_colors), result.colors)
        # NumPy colours alike; the copies of a split carry their point's colour.
        raw = pcl_wrap.wrap(points[:800], colors=colours[:800], output="raw", manifold=True)
        self.assertGreater(len(raw.copies), 0)
        np.testing.assert_array_equal(raw.colors[800:], colours[:800][raw.copies])
        self.assertIsNone(pcl_wrap.wrap(points).colors)

    @unittest.skipUnless(EXAMPLE and DATA and CLI, "needs PCL_WRAP_EXAMPLE, PCL_WRAP_DATA_DIR and PCL_WRAP_CLI")
    def test_the_example_wraps_the_bunny(self):
        import open3d as o3d
        source = os.path.join(DATA, "bunny00_points.ply")
        with tempfile.TemporaryDirectory() as work:
            target = os.path.join(work, "bunny.ply")
            run = subprocess.run([sys.executable, EXAMPLE, source, target], check=True, capture_output=True, text=True)
            self.assertIn("closed manifold: True", run.stdout)
            mesh = o3d.io.read_triangle_mesh(target)
            cli = os.path.join(work, "cli.obj")
            subprocess.run([CLI, source, cli, "--quiet"], check=True)
            np.testing.assert_array_equal(np.asarray(mesh.triangles), read_obj_triangles(cli))
        self.assertEqual(len(mesh.vertices), 37706)


if __name__ == "__main__":
    unittest.main()

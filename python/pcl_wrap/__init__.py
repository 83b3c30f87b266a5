# SPDX-License-Identifier: GPL-3.0-or-later
# Copyright (C) 2026 the pcl_wrap authors
"""Wrap surface reconstruction (Edelsbrunner) on NumPy point arrays.

    import numpy as np, pcl_wrap
    result = pcl_wrap.wrap(points)                 # points: (n, 3) float32 or float64
    result.vertices, result.triangles              # (k, 3) float64, (m, 3) indices into vertices
    mesh = pcl_wrap.to_open3d(result)              # an open3d.geometry.TriangleMesh

By default the surface is an oriented 2-manifold through the points, closed, or one open sheet for
a single layer (docs/surface.md); output="raw" gives the paper's W = Bd X. The options are the C++ WrapParameters (docs/design.md).
"""

import numpy as np

from ._core import Filtration, Region, Threshold, WrapParameters, Output, SinkDeletion
from ._core import compute as _compute
from ._core import median_spacing as _median_spacing

__all__ = ["wrap", "to_open3d", "median_spacing", "Threshold", "Region", "Filtration",
           "WrapResult", "SIMPLEX_CLASSES"]

#: The simplex classes of the complex (WrapResult.complex[k]["classes"] holds their indices).
SIMPLEX_CLASSES = ("centered", "confident", "equivocal")

_DELETIONS = {"front": SinkDeletion.front, "global": SinkDeletion.global_}
_OUTPUTS = {"surface": Output.surface, "closed": Output.closed, "raw": Output.raw}


class WrapResult:
    """What wrap() returns. Point indices: 0..n-1 are the input rows (skipped rows included),
    n + j is a copy of input point copies[j] (made where the surface touches itself).

    vertices          (k, 3) float64: the input points, then the copies
    triangles         (m, 3) int64, oriented outwards
    skipped           input rows with a non-finite coordinate or weight
    duplicates        (d, 2): a row at the same position as a kept row, and that row
    hidden            weighted input: points whose power cell is empty (never on the surface)
    copies            the input point each appended vertex copies
    dangling_edges    raw output: (e, 2) edges of X with no triangle
    isolated_vertices raw output: vertices of X with no edge
    statistics        dict: counts, the deletion's numbers, "timings" (seconds per stage)
    complex           with keep_complex=True: for k = 0..3 a dict with "vertices" ((s, k+1)
                      point indices), "classes" (indices into SIMPLEX_CLASSES), "in_x" (bool)
                      and, with filtration=True, "values"; otherwise None
    w                 with keep_complex=True: the paper's W = Bd X whatever the output, a dict
                      of triangles, dangling_edges and isolated_vertices; otherwise None
    filtration        with filtration=True: a Filtration (sink_sizes, x_size(delta),
                      surface(delta)); otherwise None
    """

    def __init__(self, vertices, fields):
        self.vertices = vertices
        self.triangles = fields["triangles"]
        self.skipped = fields["skipped"]
        self.duplicates = fields["duplicates"]
        self.hidden = fields["hidden"]
        self.copies = fields["copies"]
        self.dangling_edges = fields["dangling_edges"]
        self.isolated_vertices = fields["isolated_vertices"]
        self.statistics = fields["statistics"]
        self.complex = fields.get("complex")
        self.w = fields.get("w")
        self.filtration = fields.get("filtration")

    def __repr__(self):
        return "<pcl_wrap.WrapResult: %d vertices, %d triangles>" % (len(self.vertices), len(self.triangles))


def _points(points):
    array = np.asarray(points)
    if array.dtype.kind not in "fiu":
        raise ValueError("points must be real numbers, not %s" % array.dtype)
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError("points must be an (n, 3) array, not shape %s" % (array.shape,))
    return np.ascontiguousarray(array, dtype=np.float64)


def _weights(weights, n):
    if weights is None:
        return None
    array = np.asarray(weights)
    if array.dtype.kind not in "fiu":
        raise ValueError("weights must be real numbers, not %s" % array.dtype)
    if array.shape != (n,):
        raise ValueError("weights must be one per point, shape (%d,), not %s" % (n, array.shape))
    array = np.ascontiguousarray(array, dtype=np.float64)
    if not np.isfinite(array).all():
        raise ValueError("weights must be finite (row %d is not)" % int(np.flatnonzero(~np.isfinite(array))[0]))
    return array


def _choice(name, value, choices):
    if value not in choices:
        raise ValueError("%s must be one of %s, not %r" % (name, ", ".join(map(repr, choices)), value))
    return choices[value]


def _parameters(options):
    p = WrapParameters()
    for name, value in options.items():
        if name == "threshold":
            if value is None:
                value = Threshold()
            if not isinstance(value, Threshold):
                raise ValueError("threshold must be a pcl_wrap.Threshold, e.g. Threshold.relative_radius(4)")
            p.threshold = value
        elif name == "region":
            if not isinstance(value, Region):
                raise ValueError("region must be a pcl_wrap.Region, e.g. Region.sphere(x, y, z, r)")
            p.region = value
        elif name == "deletion":
            p.deletion = _choice(name, value, _DELETIONS)
        elif name == "output":
            p.output = _choice(name, value, _OUTPUTS)
        elif name in ("manifold", "keep_complex", "filtration"):
            if not isinstance(value, (bool, np.bool_)):
                raise ValueError("%s must be True or False, not %r" % (name, value))
            setattr(p, name, bool(value))
        elif name == "viewpoint":
            if value is not None:
                point = np.asarray(value, dtype=np.float64)
                if point.shape != (3,) or not np.isfinite(point).all():
                    raise ValueError("viewpoint must be three finite numbers (x, y, z), not %r" % (value,))
                value = tuple(float(c) for c in point)
            p.viewpoint = value
        elif name == "num_threads":
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 0 <= value <= 4096:
                raise ValueError("num_threads must be a whole number from 0 (all cores) to 4096, not %r" % (value,))
            p.num_threads = int(value)
        elif name == "weight_scale":
            if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) \
                    or not np.isfinite(value):
                raise ValueError("weight_scale must be a finite number, not %r" % (value,))
            p.weight_scale = float(value)
        else:
            raise ValueError("unknown option %r; the options are: threshold, deletion, region, output, "
                             "viewpoint, manifold, num_threads, weight_scale, keep_complex, filtration" % name)
    if p.filtration:
        p.keep_complex = True  # the filtration's values live in the complex
    return p


def wrap(points, weights=None, **options):
    """The Wrap of (n, 3) points: a WrapResult.

    points    float32 or float64 (any integer type too), C or Fortran order; rows with a
              non-finite coordinate are skipped (see WrapResult.skipped)
    weights   None, or one finite weight per point: a squared radius (power distance
              |x - p|^2 - w); weighted points whose power cell is empty are hidden
    options   threshold     a Threshold: which sinks to delete to wrap tighter, e.g.
                            Threshold.relative_radius(4); default: none (the basic wrap)
              deletion      "front" (default) or "global"
              region        a Region: local modification (front deletion with a size threshold)
              output        "surface" (default: an oriented 2-manifold through the points, closed,
                            or one open sheet for a single layer such as a terrain), "closed" (a
                            single layer too closed, its points copied per side) or "raw" (the
                            paper's W)
              viewpoint     (x, y, z): where the points were seen from; an open sheet faces it
                            (default: up, +z)
              manifold      raw output split into a closed 2-manifold (default False)
              num_threads   0 (default: all cores) or a thread count for this call
              weight_scale  every weight multiplied by this (default 1)
              keep_complex  return the Delaunay complex with classes and X (default False)
              filtration    compute the wrap filtration (default False; keeps the complex)
    Raises ValueError for a wrong shape or type, non-finite weights, an unknown option or a
    parameter without meaning. The computation runs without the GIL.
    """
    array = _points(points)
    parameters = _parameters(options)
    fields = _compute(array, _weights(weights, len(array)), parameters)
    copies = fields["copies"]
    vertices = np.concatenate([array, array[copies]])  # a copy: never the caller's array
    return WrapResult(vertices, fields)


def median_spacing(points):
    """The median nearest-neighbour distance of the distinct finite points (exact, from their
    Delaunay triangulation): what Threshold.relative_radius is relative to."""
    return _median_spacing(_points(points))


def to_open3d(result):
    """result's surface as an open3d.geometry.TriangleMesh with the same vertices (input rows
    first, so skipped rows stay as unreferenced NaN vertices) and triangles. Needs Open3D."""
    try:
        import open3d
    except ImportError as error:
        raise ImportError("pcl_wrap.to_open3d needs Open3D (pip install open3d, or Debian's "
                          "python3-open3d)") from error
    mesh = open3d.geometry.TriangleMesh()
    mesh.vertices = open3d.utility.Vector3dVector(np.ascontiguousarray(result.vertices, dtype=np.float64))
    mesh.triangles = open3d.utility.Vector3iVector(np.ascontiguousarray(result.triangles, dtype=np.int32))
    return mesh

# SPDX-License-Identifier: GPL-3.0-or-later
# Copyright (C) 2026 the pcl_wrap authors
"""Wrap surface reconstruction (Edelsbrunner) on NumPy arrays and Open3D point clouds.

    import numpy as np, pcl_wrap
    result = pcl_wrap.wrap(points)                 # (n, 3) array, or an open3d PointCloud
    result.vertices, result.triangles              # (k, 3) float64, (m, 3) indices into vertices
    mesh = pcl_wrap.to_open3d(result)              # an open3d.geometry.TriangleMesh

By default the surface is an oriented 2-manifold through the points, closed, or one open sheet for
a single layer such as a terrain; output="raw" gives the paper's W = Bd X. Colours and normals
given with the points follow them to the mesh's vertices.
"""

from typing import Any, Dict, Optional, Sequence, Tuple, Union
import json

import numpy as np

from ._core import Filtration, Output, Region, SinkDeletion, Threshold, WrapParameters
from ._core import __version__
from ._core import compute as _compute
from ._core import median_spacing as _median_spacing

__all__ = ["wrap", "to_open3d", "median_spacing", "Threshold", "Region", "Filtration", "Output",
           "SinkDeletion", "WrapResult", "SIMPLEX_CLASSES", "__version__"]

#: The simplex classes of the complex (WrapResult.complex[k]["classes"] holds their indices).
SIMPLEX_CLASSES = ("centered", "confident", "equivocal")

_DELETIONS = {"front": SinkDeletion.front, "global": SinkDeletion.global_}
_OUTPUTS = {"surface": Output.surface, "closed": Output.closed, "raw": Output.raw}


class WrapResult:
    """What wrap() returns. Point indices: 0..n-1 are the input rows (skipped rows included),
    n + j is a copy of input point copies[j] (made where the surface touches itself).

    vertices          (k, 3) float64: the input points, then the copies
    triangles         (m, 3) int64, oriented outwards
    colors            (k, 3) float64 in [0, 1], when the input had colours; else None
    normals           (k, 3) float64, when the input had normals; else None
    skipped           input rows with a non-finite coordinate or weight
    duplicates        (d, 2): a row at the same position as a kept row, and that row
    hidden            weighted input: points whose power cell is empty (never on the surface)
    apart             default surface: points apart from all others (outliers), left off it
    off_surface       every input row used that the surface does not pass through (apart
                      included); each row is on the surface, off it, skipped, hidden or a
                      duplicate
    copies            the input point each appended vertex copies
    dangling_edges    raw output: (e, 2) edges of X with no triangle
    isolated_vertices raw output: vertices of X with no edge
    statistics        dict, the keys of the command-line tool's --stats-json: "points",
                      "spacing" (the median nearest-neighbour distance), "deletion", "timings"
                      (seconds per stage and "total"), ...
    complex           with keep_complex=True: for k = 0..3 a dict with "vertices" ((s, k+1)
                      point indices), "classes" (indices into SIMPLEX_CLASSES), "in_x" (bool)
                      and, with filtration=True, "values"; otherwise None
    w                 with keep_complex=True: the paper's W = Bd X whatever the output, a dict
                      of triangles, dangling_edges and isolated_vertices; otherwise None
    filtration        with filtration=True: a Filtration (sink_sizes, x_size(delta),
                      surface(delta)); otherwise None
    """

    def __init__(self, vertices: np.ndarray, fields: Dict[str, Any],
                 colors: Optional[np.ndarray], normals: Optional[np.ndarray]):
        copies = fields["copies"]
        self.vertices = vertices
        self.triangles = fields["triangles"]
        self.colors = None if colors is None else np.concatenate([colors, colors[copies]])
        self.normals = None if normals is None else np.concatenate([normals, normals[copies]])
        self.skipped = fields["skipped"]
        self.duplicates = fields["duplicates"]
        self.hidden = fields["hidden"]
        self.apart = fields["apart"]
        self.off_surface = fields["off_surface"]
        self.copies = copies
        self.dangling_edges = fields["dangling_edges"]
        self.isolated_vertices = fields["isolated_vertices"]
        self.statistics = json.loads(fields["statistics"])
        self.complex = fields.get("complex")
        self.w = fields.get("w")
        self.filtration = fields.get("filtration")

    def __repr__(self) -> str:
        return "<pcl_wrap.WrapResult: %d vertices, %d triangles>" % (len(self.vertices), len(self.triangles))


def _real_array(name: str, values: Any, shape: Tuple[Optional[int], ...]) -> np.ndarray:
    """values as a C-ordered float64 array of the given shape (None: any length)."""
    array = np.asarray(values)
    if array.dtype.kind not in "fiu":
        raise ValueError("%s must be real numbers, not %s" % (name, array.dtype))
    if array.ndim != len(shape) or any(want is not None and got != want for got, want in zip(array.shape, shape)):
        wanted = "(%s)" % ", ".join("n" if want is None else str(want) for want in shape)
        if len(shape) == 1:
            wanted = "one per point, shape (%d,)" % shape[0]
        raise ValueError("%s must be %s, not shape %s" % (name, wanted, array.shape))
    return np.ascontiguousarray(array, dtype=np.float64)


def _open3d_cloud(points: Any) -> Optional[Any]:
    """points when it is an open3d.geometry.PointCloud (without importing Open3D otherwise)."""
    kind = type(points)
    if kind.__name__ == "PointCloud" and kind.__module__.startswith("open3d"):
        return points
    return None


def _choice(name: str, value: Any, choices: Dict[str, Any]) -> Any:
    if value in choices.values():  # the exported enum itself
        return value
    if value not in choices:
        raise ValueError("%s must be one of %s (or pcl_wrap.%s), not %r"
                         % (name, ", ".join(map(repr, choices)), type(next(iter(choices.values()))).__name__,
                            value))
    return choices[value]


def _flag(name: str, value: Any) -> bool:
    if not isinstance(value, (bool, np.bool_)):
        raise ValueError("%s must be True or False, not %r" % (name, value))
    return bool(value)


def _parameters(threshold, deletion, region, output, viewpoint, manifold, num_threads, weight_scale,
                keep_complex, filtration) -> WrapParameters:
    p = WrapParameters()
    if threshold is not None:
        if not isinstance(threshold, Threshold):
            raise ValueError("threshold must be a pcl_wrap.Threshold, e.g. Threshold.relative_radius(4)")
        p.threshold = threshold
    if region is not None:
        if not isinstance(region, Region):
            raise ValueError("region must be a pcl_wrap.Region, e.g. Region.sphere(x, y, z, r)")
        p.region = region
    p.deletion = _choice("deletion", deletion, _DELETIONS)
    p.output = _choice("output", output, _OUTPUTS)
    if viewpoint is not None:
        point = np.asarray(viewpoint, dtype=np.float64)
        if point.shape != (3,) or not np.isfinite(point).all():
            raise ValueError("viewpoint must be three finite numbers (x, y, z), not %r" % (viewpoint,))
        p.viewpoint = tuple(float(c) for c in point)
    p.manifold = _flag("manifold", manifold)
    p.keep_complex = _flag("keep_complex", keep_complex)
    p.filtration = _flag("filtration", filtration)
    if p.filtration:
        p.keep_complex = True  # the filtration's values live in the complex
    if isinstance(num_threads, bool) or not isinstance(num_threads, (int, np.integer)) or not 0 <= num_threads <= 4096:
        raise ValueError("num_threads must be a whole number from 0 (all cores) to 4096, not %r" % (num_threads,))
    p.num_threads = int(num_threads)
    if isinstance(weight_scale, bool) or not isinstance(weight_scale, (int, float, np.integer, np.floating)) \
            or not np.isfinite(weight_scale):
        raise ValueError("weight_scale must be a finite number, not %r" % (weight_scale,))
    p.weight_scale = float(weight_scale)
    return p


def wrap(points: Any,
         weights: Optional[Any] = None,
         *,
         colors: Optional[Any] = None,
         normals: Optional[Any] = None,
         threshold: Optional[Threshold] = None,
         deletion: Union[str, SinkDeletion] = "front",
         region: Optional[Region] = None,
         output: Union[str, Output] = "surface",
         viewpoint: Optional[Sequence[float]] = None,
         manifold: bool = False,
         num_threads: int = 0,
         weight_scale: float = 1.0,
         keep_complex: bool = False,
         filtration: bool = False) -> WrapResult:
    """The Wrap of the points: a WrapResult.

    points        an (n, 3) array (float32, float64 or integers; C or Fortran order), or an
                  open3d.geometry.PointCloud, whose colours and normals are taken too; rows with
                  a non-finite coordinate are skipped (see WrapResult.skipped)
    weights       None, or one weight per point: a squared radius (power distance
                  |x - p|^2 - w); a row whose weight is not finite is skipped; weighted points
                  whose power cell is empty are hidden
    colors        None, or (n, 3) colours in [0, 1]: WrapResult.colors, to_open3d's colours
    normals       None, or (n, 3) normals: WrapResult.normals, to_open3d's normals
    threshold     a Threshold: which sinks to delete to wrap tighter, e.g.
                  Threshold.relative_radius(4); default: none (the basic wrap)
    deletion      "front" (default) or "global", or a pcl_wrap.SinkDeletion
    region        a Region: local modification (front deletion with a size threshold)
    output        "surface" (default: an oriented 2-manifold through the points, closed, or one
                  open sheet for a single layer such as a terrain), "closed" (a single layer too
                  closed, its points copied per side) or "raw" (the paper's W), or a
                  pcl_wrap.Output
    viewpoint     (x, y, z): where the points were seen from; an open sheet faces it (default:
                  up, +z)
    manifold      with output="raw": W split into a closed 2-manifold (default False)
    num_threads   0 (default: all cores) or a thread count for this call
    weight_scale  every weight multiplied by this (default 1)
    keep_complex  return the Delaunay complex with classes and X (default False)
    filtration    compute the wrap filtration (default False; keeps the complex)

    Raises ValueError for a wrong shape or type or a parameter without meaning, and
    KeyboardInterrupt on Ctrl-C (checked between the stages). The computation runs without the
    GIL.
    """
    cloud = _open3d_cloud(points)
    if cloud is not None:
        points = np.asarray(cloud.points)
        if colors is None and cloud.has_colors():
            colors = np.asarray(cloud.colors)
        if normals is None and cloud.has_normals():
            normals = np.asarray(cloud.normals)
    array = _real_array("points", points, (None, 3))
    n = len(array)
    if colors is not None:
        colors = _real_array("colors", colors, (n, 3))
    if normals is not None:
        normals = _real_array("normals", normals, (n, 3))
    if weights is not None:
        weights = _real_array("weights", weights, (n,))
    parameters = _parameters(threshold, deletion, region, output, viewpoint, manifold, num_threads, weight_scale,
                             keep_complex, filtration)
    if parameters.manifold and parameters.output != Output.raw:
        raise ValueError("manifold=True splits the raw W (output='raw'); the default surface is a 2-manifold already")
    fields = _compute(array, weights, parameters)
    vertices = np.concatenate([array, array[fields["copies"]]])  # a copy: never the caller's array
    return WrapResult(vertices, fields, colors, normals)


def median_spacing(points: Any) -> float:
    """The median nearest-neighbour distance of the distinct finite points (exact, from their
    Delaunay triangulation): what Threshold.relative_radius is relative to."""
    cloud = _open3d_cloud(points)
    return _median_spacing(_real_array("points", np.asarray(cloud.points) if cloud is not None else points, (None, 3)))


def to_open3d(result: WrapResult) -> Any:
    """result's surface as an open3d.geometry.TriangleMesh, with the colours and normals the input
    had. Its vertices are result.vertices without the skipped (non-finite) rows, in order, and
    the triangles index them. Needs Open3D."""
    try:
        import open3d
    except ImportError as error:
        raise ImportError("pcl_wrap.to_open3d needs Open3D (pip install open3d, or Debian's "
                          "python3-open3d)") from error
    finite = np.isfinite(result.vertices).all(axis=1)
    renumber = np.cumsum(finite) - 1  # a kept row's index among the kept rows
    mesh = open3d.geometry.TriangleMesh()
    mesh.vertices = open3d.utility.Vector3dVector(np.ascontiguousarray(result.vertices[finite], dtype=np.float64))
    mesh.triangles = open3d.utility.Vector3iVector(np.ascontiguousarray(renumber[result.triangles], dtype=np.int32))
    if result.colors is not None:
        mesh.vertex_colors = open3d.utility.Vector3dVector(np.ascontiguousarray(result.colors[finite]))
    if result.normals is not None:
        mesh.vertex_normals = open3d.utility.Vector3dVector(np.ascontiguousarray(result.normals[finite]))
    return mesh

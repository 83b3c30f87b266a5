// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// pcl_wrap._core: computeWrap on NumPy arrays. The Python package (pcl_wrap/__init__.py) checks
// the arguments and gives them names; this module converts, computes without the GIL, and hands
// back arrays.
#include <pcl_wrap/compute_wrap.h>
#include <pcl_wrap/statistics_json.h>
#include <pcl_wrap/version.h>
#include <pcl_wrap/worker_threads.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace pcl_wrap;

namespace
{

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

/** An array of \a T of the given shape, filled from \a values (as many as the shape holds). */
template <typename T, typename Source>
py::array_t<T>
filled (const Source* values, std::vector<py::ssize_t> shape)
{
  py::array_t<T> out (shape);
  T* o = out.mutable_data ();
  for (py::ssize_t i = 0; i < out.size (); ++i)
    o[i] = static_cast<T> (values[i]);
  return out;
}

template <typename T, typename Source>
py::array_t<T>
matrix (const Source* values, std::size_t rows, std::size_t columns)
{
  return filled<T> (values, {py::ssize_t (rows), py::ssize_t (columns)});
}

template <typename T, typename Source>
py::array_t<T>
vector (const std::vector<Source>& values)
{
  return filled<T> (values.data (), {py::ssize_t (values.size ())});
}

py::dict
surface (const WrapSurface& w)
{
  py::dict d;
  d["triangles"] =
      matrix<std::int64_t> (w.triangles.empty () ? nullptr : w.triangles[0].data (), w.triangles.size (), 3);
  d["dangling_edges"] = matrix<std::int64_t> (w.dangling_edges.empty () ? nullptr : w.dangling_edges[0].data (),
                                              w.dangling_edges.size (), 2);
  d["isolated_vertices"] = vector<std::int64_t> (w.isolated_vertices);
  return d;
}

py::list
complex (const WrapResult& r)
{
  py::list dimensions;
  for (std::size_t k = 0; k < r.complex.size (); ++k)
  {
    const SimplexList& list = r.complex[k];
    py::dict d;
    d["vertices"] = matrix<std::int64_t> (list.vertices.data (), list.size (), k + 1);
    d["classes"] = vector<std::uint8_t> (list.classes);
    d["in_x"] = vector<bool> (list.in_x);
    if (!list.values.empty ())
      d["values"] = vector<double> (list.values);
    dimensions.append (d);
  }
  return dimensions;
}

std::vector<Point3>
positionsOf (const Doubles& points)
{
  if (points.ndim () != 2 || points.shape (1) != 3)
    throw std::invalid_argument ("points must be an (n, 3) array");
  std::vector<Point3> positions (static_cast<std::size_t> (points.shape (0)));
  if (!positions.empty ())
    std::memcpy (positions.data (), points.data (), positions.size () * sizeof (Point3));
  return positions;
}

/** The construction on (n, 3) points and optional weights; a dict of arrays back. */
py::dict
compute (const Doubles& points, const py::object& weights_or_none, const WrapParameters& parameters)
{
  const std::vector<Point3> positions = positionsOf (points);
  std::vector<double> weights;
  if (!weights_or_none.is_none ())
  {
    const Doubles w = weights_or_none.cast<Doubles> ();
    if (w.ndim () != 1)
      throw std::invalid_argument ("weights must be a 1-D array");
    weights.assign (w.data (), w.data () + w.size ());
  }

  // Between stages, and within the triangulation, the GIL is taken back for a moment to see
  // whether Ctrl-C was pressed: the KeyboardInterrupt then ends the computation.
  const auto check_signals = [] {
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals () != 0)
      throw py::error_already_set ();
  };
  WrapResult result;
  {
    py::gil_scoped_release release; // other Python threads run while the wrap is computed
    result = computeWrap (
        positions, weights, parameters, [&] (const std::string&, double) { check_signals (); },
        [&] (const std::string&, double) { check_signals (); });
  }

  py::dict out = surface (result.surface);
  out["skipped"] = vector<std::int64_t> (result.skipped);
  out["hidden"] = vector<std::int64_t> (result.hidden);
  out["apart"] = vector<std::int64_t> (result.apart);
  out["off_surface"] = vector<std::int64_t> (result.off_surface);
  out["copies"] = vector<std::int64_t> (result.copies);
  std::vector<std::int64_t> duplicates;
  for (const auto& [duplicate, kept] : result.duplicates)
    duplicates.insert (duplicates.end (), {duplicate, kept});
  out["duplicates"] = matrix<std::int64_t> (duplicates.data (), result.duplicates.size (), 2);
  out["statistics"] = statisticsJson (result); // the package reads it: the CLI's keys
  if (parameters.keep_complex)
  {
    out["complex"] = complex (result);
    out["w"] = surface (result.w);
  }
  if (!result.filtration.empty ())
    out["filtration"] = result.filtration;
  return out;
}

/** The name of a threshold's kind, as its Python factory is named. */
const char*
kindName (const Threshold& t)
{
  switch (t.kind ())
  {
  case Threshold::Kind::size: return "size";
  case Threshold::Kind::relative_radius: return "relative_radius";
  case Threshold::Kind::largest: return "largest";
  default: return "none";
  }
}

/** A child forked while the worker threads live would compute on one thread: they are ended
  * before each fork (multiprocessing's default way to start a process on Linux). */
void
endWorkersBeforeFork ()
{
  py::gil_scoped_release release;
  endWorkerThreads ();
}

} // namespace

PYBIND11_MODULE (_core, m)
{
  m.doc () = "pcl_wrap's engine; use the functions of the pcl_wrap package";
  m.attr ("__version__") = PCL_WRAP_VERSION;
  py::module_::import ("os").attr ("register_at_fork") (py::arg ("before") = py::cpp_function (&endWorkersBeforeFork));

  py::class_<Threshold> threshold (m, "Threshold",
                                   "Which sinks the construction deletes to wrap tighter (none by default).");
  threshold.def (py::init<> (), "No deletion: the basic wrap.")
      .def_static ("size", &Threshold::size, py::arg ("delta"), "Sinks of squared radius larger than delta.")
      .def_static ("radius", &Threshold::radius, py::arg ("radius"), "Sinks of radius larger than radius.")
      .def_static ("relative_radius", &Threshold::relativeRadius, py::arg ("factor"),
                   "Sinks of radius larger than factor times the median nearest-neighbour distance.")
      .def_static ("largest", &Threshold::largest, py::arg ("count"),
                   "The count largest sinks (always a global deletion).")
      .def_property_readonly ("kind", &kindName)
      .def_property_readonly ("value", &Threshold::value)
      .def_property_readonly ("count", &Threshold::count)
      .def ("__repr__", [] (const Threshold& t) {
        switch (t.kind ())
        {
        case Threshold::Kind::none: return std::string ("Threshold()");
        case Threshold::Kind::largest: return "Threshold.largest(" + std::to_string (t.count ()) + ")";
        default:
          return std::string ("Threshold.") + kindName (t) + "(" + std::string (py::repr (py::float_ (t.value ()))) +
                 ")";
        }
      });

  py::class_<Region> (m, "Region", "A closed ball or axis-aligned box for local modification.")
      .def (py::init<> (), "Everywhere: no restriction.")
      .def_static ("sphere", &Region::sphere, py::arg ("x"), py::arg ("y"), py::arg ("z"), py::arg ("r"))
      .def_static ("box", &Region::box, py::arg ("x0"), py::arg ("y0"), py::arg ("z0"), py::arg ("x1"), py::arg ("y1"),
                   py::arg ("z1"), "The box from its lowest corner to its highest.")
      .def_property_readonly ("shape",
                              [] (const Region& r) {
                                return r.shape == Region::Shape::sphere ? "sphere"
                                       : r.shape == Region::Shape::box  ? "box"
                                                                        : "everywhere";
                              })
      .def_property_readonly ("values", [] (const Region& r) { return r.values; });

  py::class_<Filtration> (m, "Filtration",
                          "X(delta) and W(delta) for any delta, from one pass over the sinks in size order.")
      .def_property_readonly ("sink_sizes", [] (const Filtration& f) { return vector<double> (f.sinkSizes ()); },
                              "The sizes of the sinks other than the outside, decreasing.")
      .def (
          "x_size", [] (const Filtration& f, double delta) { return f.xSize (delta); }, py::arg ("delta"),
          "The number of simplices of X(delta) per dimension.")
      .def (
          "surface", [] (const Filtration& f, double delta) { return surface (f.surface (delta)); }, py::arg ("delta"),
          "W(delta): a dict of triangles, dangling_edges and isolated_vertices (point indices).");

  py::enum_<SinkDeletion> (m, "SinkDeletion")
      .value ("front", SinkDeletion::front)
      .value ("global_", SinkDeletion::global);
  py::enum_<Output> (m, "Output")
      .value ("surface", Output::surface)
      .value ("closed", Output::closed)
      .value ("raw", Output::raw);

  py::class_<WrapParameters> (m, "WrapParameters")
      .def (py::init<> ())
      .def_readwrite ("keep_complex", &WrapParameters::keep_complex)
      .def_readwrite ("num_threads", &WrapParameters::num_threads)
      .def_readwrite ("weight_scale", &WrapParameters::weight_scale)
      .def_readwrite ("threshold", &WrapParameters::threshold)
      .def_readwrite ("deletion", &WrapParameters::deletion)
      .def_readwrite ("region", &WrapParameters::region)
      .def_readwrite ("output", &WrapParameters::output)
      .def_readwrite ("viewpoint", &WrapParameters::viewpoint)
      .def_readwrite ("manifold", &WrapParameters::manifold)
      .def_readwrite ("filtration", &WrapParameters::filtration);

  m.def ("compute", &compute, py::arg ("points"), py::arg ("weights"), py::arg ("parameters"),
         "computeWrap on a C-ordered (n, 3) float64 array and optional weights.");
  m.def ("median_spacing", [] (const Doubles& points) {
    const std::vector<Point3> positions = positionsOf (points);
    py::gil_scoped_release release;
    return medianSpacing (positions);
  });
}

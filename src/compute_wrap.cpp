// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The pipeline: points -> triangulation -> simplicial complex -> classification -> retraction ->
// boundary. Each arrow is one file of src/detail.
#include <pcl_wrap/compute_wrap.h>

#include "filtration_data.h"

#include "detail/boundary.h"
#include "detail/classification.h"
#include "detail/input_points.h"
#include "detail/manifold_split.h"
#include "detail/parallel_for_each.h"
#include "detail/power_predicates.h"
#include "detail/regular_triangulation.h"
#include "detail/retraction.h"
#include "detail/simplicial_complex.h"
#include "detail/sink_deletion.h"
#include "detail/solid_labelling.h"
#include "detail/solid_repair.h"
#include "detail/stage_clock.h"
#include "detail/wrap_filtration.h"

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace pcl_wrap
{

const char*
toString (SimplexClass c)
{
  switch (c)
  {
  case SimplexClass::centered: return "centered";
  case SimplexClass::confident: return "confident";
  case SimplexClass::equivocal: return "equivocal";
  }
  return "?";
}

std::vector<PointIndex>
WrapResult::xSimplices (int k) const
{
  std::vector<PointIndex> out;
  if (k < 0 || k > 3)
    return out;
  const SimplexList& list = complex[k];
  for (std::size_t s = 0; s < list.size (); ++s)
    if (list.in_x[s])
      out.insert (out.end (), list.vertices.begin () + (k + 1) * s, list.vertices.begin () + (k + 1) * (s + 1));
  return out;
}

namespace
{

using namespace detail;

std::array<SimplexList, 4>
inInputIndices (const SimplicialComplex& complex, const Classification& classification, const Retraction& x,
                const std::vector<PointIndex>& input_of_vertex)
{
  std::array<SimplexList, 4> lists;
  for (int k = 0; k <= 3; ++k)
  {
    SimplexList& list = lists[k];
    list.vertices.reserve ((k + 1) * complex.size (k));
    list.classes.assign (classification.classes[k].begin (), classification.classes[k].end ());
    list.in_x.resize (complex.size (k));
    for (SimplexId s = 0; s < complex.size (k); ++s)
    {
      list.in_x[s] = x.inY ({k, s});
      for (int i = 0; i <= k; ++i)
        list.vertices.push_back (input_of_vertex[complex.vertex (k, s, i)]);
    }
  }
  return lists;
}

/** Rejects parameters that have no meaning, before any work. */
void
checkParameters (const WrapParameters& p)
{
  const auto fail = [] (const std::string& what) { throw std::invalid_argument ("computeWrap: " + what); };
  const Threshold& t = p.threshold;
  if (t.kind () == Threshold::Kind::size && std::isnan (t.value ()))
    fail ("the threshold size is NaN");
  if (t.kind () == Threshold::Kind::relative_radius && !(t.value () > 0 && std::isfinite (t.value ())))
    fail ("a relative radius must be finite and > 0");
  if (t.kind () == Threshold::Kind::largest && t.count () == 0)
    fail ("the largest sinks: a count >= 1");
  if (!std::isfinite (p.weight_scale))
    fail ("weight_scale must be finite");
  const Region& r = p.region;
  if (r.shape == Region::Shape::everywhere)
    return;
  for (double v : r.values)
    if (!std::isfinite (v))
      fail ("region coordinates must be finite");
  if (r.shape == Region::Shape::sphere && r.values[3] < 0)
    fail ("region sphere radius must be >= 0");
  if (r.shape == Region::Shape::box && !(r.values[0] <= r.values[3] && r.values[1] <= r.values[4] &&
                                         r.values[2] <= r.values[5]))
    fail ("region box corners must be lowest then highest");
  if (p.deletion != SinkDeletion::front || t.kind () == Threshold::Kind::largest)
    fail ("a region (local modification) works with front deletion only");
  if (!t.deletes ())
    fail ("a region (local modification) needs a size threshold");
}

WrapResult
computeInCurrentArena (const std::vector<Point3>& points, const std::vector<double>& weights,
                       const WrapParameters& parameters, const StageObserver& observer);

} // namespace

WrapResult
computeWrap (const std::vector<Point3>& points, const WrapParameters& parameters, const StageObserver& observer)
{
  return computeWrap (points, {}, parameters, observer);
}

WrapResult
computeWrap (const std::vector<Point3>& points, const std::vector<double>& weights, const WrapParameters& parameters,
             const StageObserver& observer)
{
  checkParameters (parameters);
  if (!weights.empty () && weights.size () != points.size ())
    throw std::invalid_argument ("computeWrap: " + std::to_string (weights.size ()) + " weights for " +
                                 std::to_string (points.size ()) + " points");
  if (parameters.num_threads == 0)
    return computeInCurrentArena (points, weights, parameters, observer);
  // A thread count of its own, for this call only: other TBB users in the process keep theirs.
  tbb::task_arena arena (static_cast<int> (parameters.num_threads));
  WrapResult result;
  arena.execute ([&] { result = computeInCurrentArena (points, weights, parameters, observer); });
  return result;
}

namespace
{

WrapResult
computeInCurrentArena (const std::vector<Point3>& points, const std::vector<double>& weights,
                       const WrapParameters& parameters, const StageObserver& observer)
{
  WrapResult result;
  WrapStatistics& stats = result.statistics;
  StageClock clock (stats, observer);

  std::vector<double> scaled (weights);
  for (double& w : scaled)
    w *= parameters.weight_scale;
  InputPoints input = selectInputPoints (points, scaled);
  scaled = {};
  stats.points_input = points.size ();
  stats.points_skipped = input.skipped.size ();
  stats.points_duplicate = input.duplicates.size ();
  result.skipped = std::move (input.skipped);
  result.duplicates = std::move (input.duplicates);
  clock.stageDone ("input");

  Triangulation triangulation = triangulate (input.positions, input.weights);
  stats.triangulation_dimension = triangulation.dimension;
  stats.points_used = triangulation.point_of_vertex.size ();
  stats.points_hidden = triangulation.hidden.size ();
  for (std::uint32_t h : triangulation.hidden)
    result.hidden.push_back (input.input_index[h]);
  // Vertex id -> input index, and the kept points in vertex order for the predicates.
  std::vector<PointIndex> input_of_vertex (triangulation.point_of_vertex.size ());
  std::vector<Point3> vertex_positions (input_of_vertex.size ());
  std::vector<double> vertex_weights (input_of_vertex.size ());
  parallelForEach (input_of_vertex.size (), [&] (std::size_t v) {
    const std::uint32_t p = triangulation.point_of_vertex[v];
    input_of_vertex[v] = input.input_index[p];
    vertex_positions[v] = input.positions[p];
    vertex_weights[v] = input.weights[p];
  });
  input = {};
  clock.stageDone ("triangulation");

  // The default surface starts here: its votes on all threads, then its flood on one thread while
  // the others build the complex and compute X.
  const bool clean_surface = parameters.output == Output::surface && triangulation.dimension == 3;
  std::optional<SolidLabelling> labelling;
  tbb::task_group flooding;
  if (clean_surface)
  {
    labelling.emplace (triangulation.top_simplices, triangulation.neighbours, vertex_positions, vertex_weights);
    clock.stageDone ("votes");
    flooding.run ([&labelling] { labelling->flood (); });
  }

  // Shared: a filtration in the result keeps the complex and the classes.
  SimplicialComplex built (triangulation.dimension, static_cast<std::uint32_t> (input_of_vertex.size ()),
                           std::move (triangulation.top_simplices), triangulation.neighbours);
  auto coface_counts = built.releaseCofaceCounts (); // the retraction's, not copied
  const auto complex_kept = std::make_shared<const SimplicialComplex> (std::move (built));
  const SimplicialComplex& complex = *complex_kept;
  // The surface stage walks from tetrahedron to tetrahedron.
  FilledInParallel<std::uint32_t> neighbours;
  if (clean_surface)
    neighbours = std::move (triangulation.neighbours);
  triangulation = {};
  clock.stageDone ("complex");

  const PowerPredicates predicates (vertex_positions, vertex_weights);
  const auto classification_kept = std::make_shared<const Classification> (classify (complex, predicates));
  const Classification& classification = *classification_kept;
  stats.perturbations = predicates.perturbations ();
  for (int k = 0; k <= 3; ++k)
    for (SimplexClass c : {SimplexClass::centered, SimplexClass::confident, SimplexClass::equivocal})
      stats.simplices[k][static_cast<int> (c)] =
          countInParallel (complex.size (k), [&] (std::size_t s) { return classification.classes[k][s] == c; });
  clock.stageDone ("classification");

  Retraction x (complex, classification, std::move (coface_counts));
  stats.collapses = x.retract ();
  clock.stageDone ("collapse");
  std::shared_ptr<const WrapFiltration> filtration;
  if (parameters.filtration)
  {
    filtration = std::make_shared<const WrapFiltration> (
        wrapFiltration (complex, classification, vertex_positions, vertex_weights));
    result.filtration = Filtration (std::make_shared<const Filtration::Data> (
        Filtration::Data{complex_kept, classification_kept, filtration, input_of_vertex}));
    recordSinks (*filtration, stats);
    clock.stageDone ("filtration");
  }
  if (parameters.threshold.deletes ())
  {
    deleteSinks (complex, classification, vertex_positions, vertex_weights, parameters, filtration.get (), x, stats);
    clock.stageDone ("deletion");
  }

  // The default surface: the boundary of a labelled solid of Delaunay tetrahedra (SolidLabelling),
  // repaired to a manifold (repairSolid); where the repair leaves the surface touching itself,
  // the pinch split of the raw output separates it.
  Boundary w;
  std::unique_ptr<Retraction> pinched_solid;
  if (clean_surface)
  {
    flooding.wait ();
    SolidLabels labels = labelling->labels (x);
    labelling.reset ();
    clock.stageDone ("labelling");
    const SolidRepair repair = labels.hull ? SolidRepair{} : repairSolid (complex, neighbours, x, labels);
    stats.tetrahedra_moved = repair.flipped;
    clock.stageDone ("repair");
    if (repair.pinched_vertices == 0)
      w = extractSolidBoundary (complex, neighbours, labels.inside);
    else
    {
      pinched_solid = std::make_unique<Retraction> (complex, classification, solidSubcomplex (complex, labels.inside));
      w = extractBoundary (complex, *pinched_solid);
    }
  }
  else
    w = extractBoundary (complex, x);
  neighbours = {};
  if (pinched_solid || (parameters.manifold && !clean_surface)) // a mended solid needs no split
  {
    ManifoldSplit split = splitPinches (complex, pinched_solid ? *pinched_solid : x, w);
    w.triangles = std::move (split.triangles);
    // Copies follow the input points: vertex id numVertices() + k -> point points.size () + k.
    for (std::size_t k = 0; k < split.copy_of.size (); ++k)
    {
      input_of_vertex.push_back (static_cast<PointIndex> (points.size () + k));
      result.copies.push_back (input_of_vertex[split.copy_of[k]]);
    }
    stats.pinch_edges_split = split.pinch_edges;
    stats.pinch_vertices_split = split.pinch_vertices;
    stats.sheet_triangles_doubled = split.sheet_triangles;
  }
  result.surface = inInputIndices (w, input_of_vertex);
  stats.w_triangles = result.surface.triangles.size ();
  stats.w_dangling_edges = result.surface.dangling_edges.size ();
  stats.w_isolated_vertices = result.surface.isolated_vertices.size ();
  for (int k = 0; k <= 3; ++k)
    stats.x_simplices[k] = countInParallel (complex.size (k), [&] (std::size_t s) {
      return x.inY ({k, static_cast<SimplexId> (s)});
    });
  if (parameters.keep_complex)
  {
    result.complex = inInputIndices (complex, classification, x, input_of_vertex);
    for (int k = 0; k <= 3 && filtration; ++k)
      result.complex[k].values = filtration->value[k];
  }
  clock.stageDone ("boundary");
  return result;
}

} // namespace

} // namespace pcl_wrap

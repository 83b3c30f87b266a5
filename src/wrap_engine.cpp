// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap_engine.h"

#include "delaunay/spacing.h"
#include "filtration_data.h"
#include "surface/single_layer.h"
#include "util/parallel_for_each.h"
#include "wrap/manifold_split.h"
#include "wrap/retraction.h"
#include "wrap/sink_deletion.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

/** The sample that schedules the labels: one vertex in this many. */
constexpr std::size_t SCHEDULE_STRIDE = 64;

} // namespace

bool
sampleIsSingleLayer (const std::vector<Point3>& positions, const std::vector<double>& weights, std::size_t stride)
{
  std::vector<Point3> p;
  std::vector<double> w;
  for (std::size_t v = 0; v < positions.size (); v += stride)
  {
    p.push_back (positions[v]);
    w.push_back (weights[v]);
  }
  WrapParameters raw;
  raw.output = Output::raw;
  WrapEngine sample (p, w, raw);
  sample.selectInput ();
  sample.triangulate ();
  sample.buildComplex ();
  if (sample.complex ().dimension () != 3)
    return false;
  sample.classify ();
  sample.collapse ();
  return isSingleLayer (sample.complex (), sample.x ());
}

bool
labelAtOnce (Output output, const std::vector<Point3>& positions, const std::vector<double>& weights, StageClock& clock)
{
  if (output == Output::closed || positions.size () < DefaultSurface::LABEL_ON_DEMAND_FROM)
    return true;
  const bool single_layer = sampleIsSingleLayer (positions, weights, SCHEDULE_STRIDE);
  clock.stageDone ("sample");
  return !single_layer;
}

WrapEngine::WrapEngine (const std::vector<Point3>& points, const std::vector<double>& weights,
                        const WrapParameters& parameters, const StageObserver& observer,
                        const ProgressObserver& progress)
  : points_ (points),
    weights_ (weights),
    parameters_ (parameters),
    observer_ (observer),
    progress_ (progress),
    clock_ (result_.statistics, observer_)
{}

WrapResult
WrapEngine::run ()
{
  selectInput ();
  triangulate ();
  startDefaultSurface ();
  buildComplex ();
  classify ();
  collapse ();
  computeFiltration ();
  deleteSinks ();
  extractSurface ();
  report ();
  return std::move (result_);
}

bool
WrapEngine::defaultSurface () const
{
  return parameters_.output != Output::raw && dimension_ == 3;
}

void
WrapEngine::selectInput ()
{
  std::vector<double> scaled (weights_);
  for (double& w : scaled)
    w *= parameters_.weight_scale;
  input_ = selectInputPoints (points_, scaled);
  WrapStatistics& stats = result_.statistics;
  stats.points_input = points_.size ();
  stats.points_skipped = input_.skipped.size ();
  stats.points_duplicate = input_.duplicates.size ();
  result_.skipped = std::move (input_.skipped);
  result_.duplicates = std::move (input_.duplicates);
  clock_.stageDone ("input");
}

void
WrapEngine::triangulate ()
{
  std::function<void (double)> progress;
  if (progress_)
    progress = [this] (double done) { progress_ ("triangulation", done); };
  triangulation_ = detail::triangulate (input_.positions, input_.weights, progress);
  dimension_ = triangulation_.dimension;
  WrapStatistics& stats = result_.statistics;
  stats.triangulation_dimension = dimension_;
  stats.points_used = triangulation_.point_of_vertex.size ();
  stats.points_hidden = triangulation_.hidden.size ();
  for (std::uint32_t h : triangulation_.hidden)
    result_.hidden.push_back (input_.input_index[h]);
  // From here on the engine speaks of vertex ids: positions and weights per vertex for the
  // predicates, and the one map back to the caller's indices.
  const std::size_t n = triangulation_.point_of_vertex.size ();
  std::vector<PointIndex> input_of_vertex (n);
  vertex_positions_.resize (n);
  vertex_weights_.resize (n);
  parallelForEach (n, [&] (std::size_t v) {
    const std::uint32_t p = triangulation_.point_of_vertex[v];
    input_of_vertex[v] = input_.input_index[p];
    vertex_positions_[v] = input_.positions[p];
    vertex_weights_[v] = input_.weights[p];
  });
  input_indices_ = InputIndices (std::move (input_of_vertex));
  input_ = {};
  clock_.stageDone ("triangulation");
}

void
WrapEngine::startDefaultSurface (std::optional<bool> label_now)
{
  if (!defaultSurface ())
    return;
  if (!label_now)
    label_now = labelAtOnce (parameters_.output, vertex_positions_, vertex_weights_, clock_);
  tetrahedra_ = Tetrahedra (std::move (triangulation_.neighbours));
  surface_ = std::make_unique<DefaultSurface> (triangulation_.top_simplices, tetrahedra_, vertex_positions_,
                                               vertex_weights_, *label_now);
  if (*label_now)
    clock_.stageDone ("votes");
}

void
WrapEngine::buildComplex ()
{
  if (defaultSurface () && !surface_) // the tests build the complex without the surface stage
    tetrahedra_ = Tetrahedra (std::move (triangulation_.neighbours));
  const FilledInParallel<std::uint32_t>& neighbours =
      defaultSurface () ? tetrahedra_.neighbourArray () : triangulation_.neighbours;
  SimplicialComplex built (dimension_, static_cast<std::uint32_t> (input_indices_.size ()),
                           std::move (triangulation_.top_simplices), neighbours);
  complex_ = std::make_shared<SimplicialComplex> (std::move (built));
  if (complex_->size (1) != 0) // reported always: it says what scale a threshold is at
    result_.statistics.spacing =
        medianNearestNeighbourDistance (complex_->vertices (1, 0), complex_->size (1), 1, vertex_positions_);
  if (defaultSurface ())
    tetrahedra_.attach (*complex_);
  triangulation_ = {};
  clock_.stageDone ("complex");
}

void
WrapEngine::classify ()
{
  const SimplicialComplex& complex = *complex_;
  predicates_ = std::make_unique<PowerPredicates> (vertex_positions_, vertex_weights_);
  classification_ = std::make_shared<const Classification> (detail::classify (complex, *predicates_));
  WrapStatistics& stats = result_.statistics;
  stats.perturbations = predicates_->perturbations ();
  for (int k = 0; k <= 3; ++k)
    for (SimplexClass c : {SimplexClass::centered, SimplexClass::confident, SimplexClass::equivocal})
      stats.simplices[k][static_cast<int> (c)] = countInParallel (
          complex.size (k), [&] (std::size_t s) { return classification_->classes[k][s] == c; });
  clock_.stageDone ("classification");
}

void
WrapEngine::collapse ()
{
  // The complex's coface counts become X's, not copied.
  x_ = std::make_unique<Subcomplex> (*complex_, complex_->releaseCofaceCounts ());
  result_.statistics.collapses = Retraction (*x_, *classification_).retract ();
#ifdef PCL_WRAP_CHECK_INVARIANTS
  checkX ();
#endif
  clock_.stageDone ("collapse");
}

void
WrapEngine::computeFiltration ()
{
  if (!parameters_.filtration)
    return;
  filtration_ = std::make_shared<const WrapFiltration> (
      wrapFiltration (*complex_, *classification_, vertex_positions_, vertex_weights_));
  result_.filtration = Filtration (std::make_shared<const Filtration::Data> (
      Filtration::Data{complex_, classification_, filtration_, input_indices_}));
  recordSinks (*filtration_, result_.statistics);
  clock_.stageDone ("filtration");
}

void
WrapEngine::deleteSinks ()
{
  if (!parameters_.threshold.deletes ())
    return;
  detail::deleteSinks (*complex_, *classification_, vertex_positions_, vertex_weights_, parameters_, filtration_.get (),
                       *x_, result_.statistics);
#ifdef PCL_WRAP_CHECK_INVARIANTS
  checkX ();
#endif
  clock_.stageDone ("deletion");
}

void
WrapEngine::extractSurface ()
{
  // X is final: the flow is needed again only to write the complex out. Let go of it (a quarter
  // of the peak memory at this point) before the surface stage allocates its own.
  if (!parameters_.keep_complex)
    classification_.reset ();
  if (!defaultSurface ())
  {
    w_ = extractBoundary (*complex_, *x_, true, inputKey ());
    return; // timed with the report, as the boundary stage
  }
  DefaultSurface::Output out = surface_->surface (
      *x_, vertex_positions_, parameters_.output == Output::closed, parameters_.viewpoint,
      [this] (std::size_t stride) { return sampleIsSingleLayer (vertex_positions_, vertex_weights_, stride); },
      inputKey (), result_.statistics, clock_);
  surface_.reset ();
  tetrahedra_ = {};
  w_ = std::move (out.w);
  split_ = std::move (out.split);
  result_.apart = input_indices_.sortedPoints (out.apart);
  result_.statistics.points_apart = result_.apart.size ();
}

void
WrapEngine::report ()
{
  const SimplicialComplex& complex = *complex_;
  WrapStatistics& stats = result_.statistics;
  if (parameters_.keep_complex)
    result_.w = input_indices_.surface (defaultSurface () ? extractBoundary (complex, *x_, true, inputKey ()) : w_);
  if (parameters_.manifold && !defaultSurface ())
    split_ = splitPinches (complex, *x_, w_);
  if (split_)
  {
    input_indices_.takeSplit (*split_, w_, points_.size (), result_);
    split_.reset ();
  }
#ifdef PCL_WRAP_CHECK_INVARIANTS
  checkSurface ();
#endif
  result_.surface = input_indices_.surface (w_);
  w_ = {};
  input_indices_.recordPointsOff (result_, points_.size ());
  stats.w_triangles = result_.surface.triangles.size ();
  stats.w_dangling_edges = result_.surface.dangling_edges.size ();
  stats.w_isolated_vertices = result_.surface.isolated_vertices.size ();
  for (int k = 0; k <= 3; ++k)
    stats.x_simplices[k] = x_->size (k);
  if (parameters_.keep_complex)
  {
    result_.complex = input_indices_.complex (complex, *classification_, *x_);
    for (int k = 0; k <= 3 && filtration_; ++k)
      result_.complex[k].values = filtration_->value[k];
  }
  clock_.stageDone ("boundary");
}

/** X is a subcomplex of Del S, and no pair of the flow is free in it: the retraction ran to its
  * end (docs/design.md §5). */
void
WrapEngine::checkX () const
{
  const SimplicialComplex& complex = *complex_;
  const Classification& c = *classification_;
  const Subcomplex& x = *x_;
  for (int k = 0; k <= complex.dimension (); ++k)
    for (SimplexId s = 0; s < complex.size (k); ++s)
    {
      const Simplex v{k, s};
      if (!x.contains (v))
        continue;
      for (int i = 0; i <= k && k > 0; ++i)
        if (!x.contains (complex.facet (k, s, i)))
          throw std::logic_error ("invariant: a simplex of X has a facet outside X");
      if (c.of (v) != SimplexClass::equivocal) // a tetrahedron never is: predecessor[3] is empty
        continue;
      const Simplex tau = c.predecessor[k][s];
      if (tau.id != NO_SIMPLEX && x.contains (tau) && x.cofaceCount (v) == static_cast<std::uint32_t> (tau.dim - k))
        throw std::logic_error ("invariant: X still has a free pair of the flow");
    }
}

/** The default surface, once split, is closed and oriented: each directed edge once, with its
  * reverse (docs/surface.md). The raw W needs nothing: it is Bd X by construction. */
void
WrapEngine::checkSurface () const
{
  if (!defaultSurface ())
    return;
  if (parameters_.output == Output::surface && result_.statistics.single_layer)
  {
    // An open sheet: every directed edge once (each edge on at most two triangles, both ways).
    std::vector<std::uint64_t> directed;
    for (const auto& t : w_.triangles)
      for (int i = 0; i < 3; ++i)
        directed.push_back ((std::uint64_t (t[i]) << 32) | t[(i + 1) % 3]);
    std::sort (directed.begin (), directed.end ());
    if (std::adjacent_find (directed.begin (), directed.end ()) != directed.end ())
      throw std::logic_error ("invariant: the open sheet is not an oriented 2-manifold");
    return;
  }
  if (!nonManifoldEdges (w_.triangles).empty ())
    throw std::logic_error ("invariant: the surface is not closed and oriented");
}

} // namespace pcl_wrap::detail

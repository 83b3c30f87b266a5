// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap_engine.h"

#include "filtration_data.h"
#include "wrap/manifold_split.h"
#include "util/parallel_for_each.h"
#include "wrap/retraction.h"
#include "wrap/sink_deletion.h"
#include "surface/solid_pinch_split.h"
#include "surface/single_layer.h"
#include "surface/solid_repair.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace pcl_wrap::detail
{

WrapEngine::WrapEngine (const std::vector<Point3>& points, const std::vector<double>& weights,
                        const WrapParameters& parameters, const StageObserver& observer)
  : points_ (points), weights_ (weights), parameters_ (parameters), observer_ (observer),
    clock_ (result_.statistics, observer_)
{}

WrapEngine::~WrapEngine ()
{
  if (!labelling_)
    return;
  try
  {
    flooding_.wait (); // a stage threw while the flood ran; its own exception, if any, is dropped
  }
  catch (...)
  {
  }
}

WrapResult
WrapEngine::run ()
{
  selectInput ();
  triangulate ();
  startSolidLabelling ();
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
WrapEngine::cleanSurface () const
{
  return parameters_.output == Output::surface && dimension_ == 3;
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
  triangulation_ = detail::triangulate (input_.positions, input_.weights);
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
WrapEngine::startSolidLabelling ()
{
  if (!cleanSurface ())
    return;
  // The votes on all threads now; the flood on one thread while the others build the complex
  // and compute X, which it needs only to break exact ties (SolidLabelling::labels()).
  neighbours_ = std::move (triangulation_.neighbours); // the labelling and the repair read them
  labelling_.emplace (triangulation_.top_simplices, neighbours_, vertex_positions_, vertex_weights_);
  clock_.stageDone ("votes");
  flooding_.run ([this] { labelling_->flood (); });
}

void
WrapEngine::buildComplex ()
{
  if (cleanSurface () && !labelling_) // the labelling took them over already when it started
    neighbours_ = std::move (triangulation_.neighbours);
  const FilledInParallel<std::uint32_t>& neighbours = cleanSurface () ? neighbours_ : triangulation_.neighbours;
  SimplicialComplex built (dimension_, static_cast<std::uint32_t> (input_indices_.size ()),
                           std::move (triangulation_.top_simplices), neighbours);
  complex_ = std::make_shared<SimplicialComplex> (std::move (built));
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
  const SimplicialComplex& complex = *complex_;
  if (!cleanSurface ())
  {
    w_ = extractBoundary (complex, *x_);
    return; // timed with the report, as the boundary stage
  }
  // The boundary of a labelled solid of Delaunay tetrahedra, repaired to a manifold; where the
  // repair leaves the surface touching itself, the pinch split of the raw output separates it.
  flooding_.wait ();
  SolidLabels labels = labelling_->labels (*x_);
  labelling_.reset ();
  clock_.stageDone ("labelling");
  const bool single_layer = !labels.hull && isSingleLayer (complex, *x_, labels.inside);
  const SolidRepair repair = labels.hull ? SolidRepair{} : repairSolid (complex, neighbours_, *x_, labels);
  result_.statistics.tetrahedra_moved = repair.flipped;
  clock_.stageDone ("repair");
  w_ = extractSolidBoundary (complex, neighbours_, labels.inside);
  if (!repair.pinched.empty ())
  {
    split_ = splitSolidPinches (complex, neighbours_, labels.inside, w_, repair.pinched);
    if (!split_) // an edge needs more than the two simple pairings: the whole split tries the rest
    {
      pinched_solid_ = std::make_unique<Subcomplex> (complex, solidSubcomplex (complex, labels.inside));
      w_ = extractBoundary (complex, *pinched_solid_);
    }
  }
  const std::size_t on_solid = single_layer ? verticesOn (w_.triangles) : 0;
  if (single_layer && on_solid < complex.numVertices ())
  {
    // The labelled solid is not Wrap's and leaves points off its surface: the points are one
    // layer, and X is that layer.
    TwoSidedShell shell = twoSidedShell (complex, vertex_positions_, neighbours_, *x_);
    if (verticesOn (shell.w.triangles) > on_solid)
    {
      w_ = std::move (shell.w);
      split_ = std::move (shell.split);
      pinched_solid_.reset ();
      result_.statistics.single_layer = true;
      result_.statistics.bridge_simplices = shell.bridges;
    }
  }
  neighbours_ = {};
}

void
WrapEngine::report ()
{
  const SimplicialComplex& complex = *complex_;
  WrapStatistics& stats = result_.statistics;
  if (pinched_solid_ || (parameters_.manifold && !cleanSurface ())) // a mended solid needs no split
    split_ = splitPinches (complex, pinched_solid_ ? *pinched_solid_ : *x_, w_);
  if (split_)
  {
    ManifoldSplit& split = *split_;
    w_.triangles = std::move (split.triangles);
    result_.copies = input_indices_.appendCopies (split.copy_of, points_.size ());
    stats.pinch_edges_split = split.pinch_edges;
    stats.pinch_vertices_split = split.pinch_vertices;
    stats.sheet_triangles_doubled = split.sheet_triangles;
    split_.reset ();
  }
#ifdef PCL_WRAP_CHECK_INVARIANTS
  checkSurface ();
#endif
  result_.surface = input_indices_.surface (w_);
  w_ = {};
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

/** The clean surface, once split, is closed and oriented: each directed edge once, with its
  * reverse (docs/surface.md). The raw W needs nothing: it is Bd X by construction. */
void
WrapEngine::checkSurface () const
{
  if (!cleanSurface () || w_.triangles.empty ())
    return;
  std::vector<std::array<std::uint32_t, 2>> edges;
  for (const auto& t : w_.triangles)
    for (int i = 0; i < 3; ++i)
      edges.push_back ({t[i], t[(i + 1) % 3]});
  std::sort (edges.begin (), edges.end ());
  if (std::adjacent_find (edges.begin (), edges.end ()) != edges.end ())
    throw std::logic_error ("invariant: the surface has an edge twice the same way");
  for (const auto& e : edges)
    if (!std::binary_search (edges.begin (), edges.end (), std::array<std::uint32_t, 2>{e[1], e[0]}))
      throw std::logic_error ("invariant: the surface has an edge with one triangle");
}

} // namespace pcl_wrap::detail

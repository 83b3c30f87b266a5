// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/input_points.h"
#include "delaunay/power_predicates.h"
#include "delaunay/regular_triangulation.h"
#include "delaunay/simplicial_complex.h"
#include "delaunay/tetrahedra.h"
#include "input_indices.h"
#include "surface/default_surface.h"
#include "util/stage_clock.h"
#include "wrap/boundary.h"
#include "wrap/classification.h"
#include "wrap/manifold_split.h"
#include "wrap/subcomplex.h"
#include "wrap/wrap_filtration.h"

#include <pcl_wrap/compute_wrap.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Does the wrap of one vertex in \a stride, along the vertex ids' Z-order curve (a sample
  * even in space), find a single layer (isSingleLayer())? */
bool
sampleIsSingleLayer (const std::vector<Point3>& positions, const std::vector<double>& weights, std::size_t stride);

/** \brief Whether the default surface's labels are computed as soon as the tetrahedra are known
  * (the votes before the complex is built, the flood beside the next stages) rather than when the
  * surface needs them: always, but for a large cloud whose even sample's wrap finds a single
  * layer (a time "sample" on \a clock), which needs no labels. It decides when, never what. */
bool
labelAtOnce (Output output, const std::vector<Point3>& positions, const std::vector<double>& weights,
             StageClock& clock);

/** \brief The Wrap construction as named stages over one state. run() calls them in the order of
  * the pipeline; the tests call the first ones alone to look at what they build.
  *
  *   selectInput -> triangulate -> startDefaultSurface -> buildComplex -> classify -> collapse
  *   -> computeFiltration -> deleteSinks -> extractSurface -> report
  *
  * The stages in between that a parameter does not ask for do nothing. Each stage ends by timing
  * itself (WrapStatistics::timings). With PCL_WRAP_CHECK_INVARIANTS defined, stages also check
  * what docs/design.md says must hold after them, and throw std::logic_error when it does not. */
class WrapEngine
{
public:
  /** \brief Keeps references to \a points, \a weights and \a parameters: they outlive the engine. */
  WrapEngine (const std::vector<Point3>& points, const std::vector<double>& weights, const WrapParameters& parameters,
              const StageObserver& observer = StageObserver (), const ProgressObserver& progress = ProgressObserver ());
  WrapEngine (const WrapEngine&) = delete;
  WrapEngine& operator= (const WrapEngine&) = delete;

  /** \brief Every stage in order; the result. */
  WrapResult run ();

  /** \brief The points with finite coordinates and weight, each position once (the largest
    * weight kept); the others are reported. */
  void selectInput ();
  /** \brief The regular (weighted Delaunay) triangulation; hidden points are reported. */
  void triangulate ();
  /** \brief The default surface's votes, then its flood as a task beside the next stages; or
    * nothing until the surface needs the labels. \a label_now says which; by default a sample
    * of the points does (a single layer needs no labels). Either way the output is the same. */
  void startDefaultSurface (std::optional<bool> label_now = std::nullopt);
  /** \brief Del S as a simplicial complex with faces, cofaces and coface counts. */
  void buildComplex ();
  /** \brief Each simplex's class and its flow (§5). */
  void classify ();
  /** \brief The retraction of Del S to X by collapses along the flow (§6). */
  void collapse ();
  /** \brief The wrap filtration (every sink deleted in size order), when asked. */
  void computeFiltration ();
  /** \brief The deletion of the sinks above the threshold, when there is one (§8). */
  void deleteSinks ();
  /** \brief W = Bd X, or the default surface (docs/surface.md), in vertex ids. */
  void extractSurface ();
  /** \brief The result in point indices, the statistics and, when asked, the complex. */
  void report ();

  const WrapResult& result () const { return result_; }
  const SimplicialComplex& complex () const { return *complex_; }
  /** \brief After extractSurface(), only with WrapParameters::keep_complex. */
  const Classification& classification () const { return *classification_; }
  const PowerPredicates& predicates () const { return *predicates_; }
  const Subcomplex& x () const { return *x_; }
  /** \brief How the tetrahedra meet, for the default surface: from buildComplex() until the
    * surface is extracted. */
  const Tetrahedra& tetrahedra () const { return tetrahedra_; }
  /** \brief Per vertex id: its position and weight. */
  const std::vector<Point3>& vertexPositions () const { return vertex_positions_; }
  const std::vector<double>& vertexWeights () const { return vertex_weights_; }
  const InputIndices& inputIndices () const { return input_indices_; }

private:
  bool defaultSurface () const;
  /** W's sheets take their turn from the input indices, so that any process that computes the
    * same W turns them alike (orientSheetTriangles). */
  std::function<std::uint32_t (std::uint32_t)> inputKey () const
  {
    return [this] (std::uint32_t v) { return input_indices_ (v); };
  }
  void checkX () const;
  void checkSurface () const;

  const std::vector<Point3>& points_;
  const std::vector<double>& weights_;
  const WrapParameters& parameters_;
  WrapResult result_;
  const StageObserver observer_; // copies: the caller's may be temporaries
  const ProgressObserver progress_;
  StageClock clock_;

  InputPoints input_;
  Triangulation triangulation_;
  int dimension_ = -1;
  std::vector<Point3> vertex_positions_;
  std::vector<double> vertex_weights_;
  InputIndices input_indices_;
  Tetrahedra tetrahedra_;                  // the default surface's walk
  std::unique_ptr<DefaultSurface> surface_; // after tetrahedra_: its flood reads them
  std::shared_ptr<SimplicialComplex> complex_; // shared with the filtration
  std::unique_ptr<PowerPredicates> predicates_;
  std::shared_ptr<const Classification> classification_;
  std::unique_ptr<Subcomplex> x_;
  std::shared_ptr<const WrapFiltration> filtration_;
  Boundary w_;
  std::optional<ManifoldSplit> split_; // the surface where it touched itself, split
};

} // namespace pcl_wrap::detail

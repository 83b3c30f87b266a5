// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "wrap/boundary.h"
#include "wrap/classification.h"
#include "util/filled_in_parallel.h"
#include "delaunay/input_points.h"
#include "input_indices.h"
#include "wrap/manifold_split.h"
#include "delaunay/power_predicates.h"
#include "delaunay/regular_triangulation.h"
#include "wrap/subcomplex.h"
#include "delaunay/simplicial_complex.h"
#include "surface/solid_labelling.h"
#include "util/stage_clock.h"
#include "wrap/wrap_filtration.h"

#include <pcl_wrap/compute_wrap.h>

#include <tbb/task_group.h>

#include <memory>
#include <optional>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The Wrap construction as named stages over one state. run() calls them in the order of
  * the pipeline; the tests call the first ones alone to look at what they build.
  *
  *   selectInput -> triangulate -> startSolidLabelling -> buildComplex -> classify -> collapse
  *   -> computeFiltration -> deleteSinks -> extractSurface -> report
  *
  * The stages in between that a parameter does not ask for do nothing. Each stage ends by timing
  * itself (WrapStatistics::timings). With PCL_WRAP_CHECK_INVARIANTS defined, stages also check
  * what docs/design.md says must hold after them, and throw std::logic_error when it does not. */
class WrapEngine
{
public:
  WrapEngine (const std::vector<Point3>& points, const std::vector<double>& weights, const WrapParameters& parameters,
              const StageObserver& observer = StageObserver ());
  WrapEngine (const WrapEngine&) = delete;
  WrapEngine& operator= (const WrapEngine&) = delete;
  /** \brief Waits for a flood still running (a stage threw). */
  ~WrapEngine ();

  /** \brief Every stage in order; the result. */
  WrapResult run ();

  /** \brief The points with finite coordinates and weight, each position once (the largest
    * weight kept); the others are reported. */
  void selectInput ();
  /** \brief The regular (weighted Delaunay) triangulation; hidden points are reported. */
  void triangulate ();
  /** \brief The clean surface's votes, then its flood as a task beside the next stages. */
  void startSolidLabelling ();
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
  /** \brief W = Bd X, or the clean surface (docs/surface.md), in vertex ids. */
  void extractSurface ();
  /** \brief The result in point indices, the statistics and, when asked, the complex. */
  void report ();

  const WrapResult& result () const { return result_; }
  const SimplicialComplex& complex () const { return *complex_; }
  const Classification& classification () const { return *classification_; }
  const PowerPredicates& predicates () const { return *predicates_; }
  const Subcomplex& x () const { return *x_; }
  /** \brief Per tetrahedron, the tetrahedron across each facet (the clean surface's walk), from
    * buildComplex() until the surface is extracted. */
  const FilledInParallel<std::uint32_t>& neighbours () const { return neighbours_; }
  /** \brief Per vertex id: its position and weight. */
  const std::vector<Point3>& vertexPositions () const { return vertex_positions_; }
  const std::vector<double>& vertexWeights () const { return vertex_weights_; }
  const InputIndices& inputIndices () const { return input_indices_; }

private:
  bool cleanSurface () const;
  void checkX () const;
  void checkSurface () const;

  const std::vector<Point3>& points_;
  const std::vector<double>& weights_;
  const WrapParameters& parameters_;
  WrapResult result_;
  const StageObserver observer_; // a copy: the caller's may be a temporary
  StageClock clock_;

  InputPoints input_;
  Triangulation triangulation_;
  int dimension_ = -1;
  std::vector<Point3> vertex_positions_;
  std::vector<double> vertex_weights_;
  InputIndices input_indices_;
  std::optional<SolidLabelling> labelling_; // engaged while its flood may run
  tbb::task_group flooding_;
  std::shared_ptr<SimplicialComplex> complex_; // shared with the filtration
  FilledInParallel<std::uint32_t> neighbours_; // the surface stage's walk
  std::unique_ptr<PowerPredicates> predicates_;
  std::shared_ptr<const Classification> classification_;
  std::unique_ptr<Subcomplex> x_;
  std::shared_ptr<const WrapFiltration> filtration_;
  Boundary w_;
  std::unique_ptr<Subcomplex> pinched_solid_; // the repaired solid, when its pinches need the whole split
  std::optional<ManifoldSplit> split_;        // W where it touched itself, split
};

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "surface/solid_labelling.h"
#include "util/filled_in_parallel.h"
#include "util/stage_clock.h"
#include "wrap/boundary.h"
#include "wrap/manifold_split.h"
#include "wrap/subcomplex.h"

#include <pcl_wrap/compute_wrap.h>

#include <tbb/task_group.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The default surface (docs/surface.md) as one stage beside the paper's construction: the
  * labelling of the Delaunay tetrahedra, started right after the triangulation and flooded while
  * the construction computes X (unless the points look like a single layer, which needs no
  * labels); then, given X, the repair into a 2-manifold, the surface read off the labels, the open
  * sheet (or the closed two-sided shell) for a single layer, and the split of what still touches
  * itself. Its policy, which of these the output is, is in surface(). */
class DefaultSurface
{
public:
  /** \brief From this many points on, the engine may leave the labelling to surface() (when a
    * sample of the points is a single layer); below, it always starts it with the construction,
    * and a single layer whose votes enclose nothing (a few points, a box's corners around its
    * centre) is its convex hull rather than a sheet. */
  static constexpr std::size_t LABEL_ON_DEMAND_FROM = 200000;

  /** \brief Where X is partly a sheet (LayerTriangles::partlySheet()), the points are also a
    * single layer when the wrap of one vertex in NOISY_LAYER_STRIDE is: on a layer, a sample at
    * four times the spacing, over which noise of a spacing is a quarter of one. A cloud of fewer
    * than 256 times that many points is sampled more densely, to keep 256 points, but one vertex
    * in 4 at most (noise of a spacing is half the sample's); one of fewer than 1,024 is not. */
  static constexpr std::size_t NOISY_LAYER_STRIDE = 16, NOISY_LAYER_SAMPLE = 256, NOISY_LAYER_DENSEST = 4;

  /** \brief The stride of the sample that judges a noisy layer of \a n points; 0 when none does. */
  static constexpr std::size_t noisyLayerStride (std::size_t n)
  {
    return n < NOISY_LAYER_DENSEST * NOISY_LAYER_SAMPLE ? 0 : std::min (NOISY_LAYER_STRIDE, n / NOISY_LAYER_SAMPLE);
  }

  /** \brief Does the wrap of one vertex in the given number (along the vertex ids) find a single
    * layer? */
  using SampleIsSingleLayer = std::function<bool (std::size_t stride)>;

  /** \brief With \a label_now, the votes on all threads, then the flood as a task beside the
    * caller's next stages; otherwise nothing until surface() needs the labels.
    * \param[in] tetrahedra four vertex ids per tetrahedron; read only here
    * \param[in] adjacency the same tetrahedra's neighbours; outlives this, and is attached to its
    *            complex before surface()
    * \param[in] positions, weights per vertex; outlive this */
  DefaultSurface (const FilledInParallel<std::uint32_t>& tetrahedra, const Tetrahedra& adjacency,
                  const std::vector<Point3>& positions, const std::vector<double>& weights, bool label_now);
  DefaultSurface (const DefaultSurface&) = delete;
  DefaultSurface& operator= (const DefaultSurface&) = delete;
  /** \brief Waits for a flood still running (the engine stopped at an exception); its own
    * exception, if any, is dropped. */
  ~DefaultSurface ();

  /** \brief Each vertex's place in the input: W's sheets are turned by it (extractBoundary()). */
  using InputKey = std::function<std::uint32_t (std::uint32_t)>;

  /** \brief The surface in vertex ids: its triangles and, where they touch themselves or a
    * single layer is doubled, their split into a closed 2-manifold. */
  struct Output
  {
    Boundary w;
    std::optional<ManifoldSplit> split;
    std::vector<std::uint32_t> apart; ///< the points apart from all others, left off (pointsApart())
  };

  /** \brief The surface, once X is known; call once. Records the stages "labelling" and
    * "repair" (or "sheet") on \a clock and what it did in \a stats.
    * \param[in] positions per vertex
    * \param[in] closed a single layer as a closed two-sided shell rather than an open sheet
    * \param[in] viewpoint where an open sheet faces, if given (openSheet())
    * \param[in] sample_is_single_layer asked only for a cloud that X leaves in doubt
    * \param[in] input_key where the output is W itself, its sheets turn as the raw output's */
  Output surface (const Subcomplex& x, const std::vector<Point3>& positions, bool closed,
                  const std::optional<Point3>& viewpoint, const SampleIsSingleLayer& sample_is_single_layer,
                  const InputKey& input_key, WrapStatistics& stats, StageClock& clock);

private:
  /** The labels, from the flood started by the constructor or, if none was, from one run now. */
  SolidLabels labelsFor (const Subcomplex& x);

  const Tetrahedra& adjacency_;
  const std::vector<Point3>& positions_;
  const std::vector<double>& weights_;
  std::optional<SolidLabelling> labelling_; ///< engaged while its flood may run
  tbb::task_group flooding_;
};

} // namespace pcl_wrap::detail

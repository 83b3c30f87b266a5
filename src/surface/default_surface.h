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

#include <cstdint>
#include <optional>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The default surface (docs/surface.md) as one stage beside the paper's construction: the
  * labelling of the Delaunay tetrahedra, started right after the triangulation and flooded while
  * the construction computes X; then, given X, the repair into a 2-manifold, the surface read off
  * the labels, the open sheet (or the closed two-sided shell) for a single layer, and the split of what still touches itself.
  * Its policy, which of these the output is, is in surface(). */
class DefaultSurface
{
public:
  /** \brief The votes, on all threads; then the flood, as a task beside the caller's next stages.
    * \param[in] tetrahedra four vertex ids per tetrahedron; read only here
    * \param[in] adjacency the same tetrahedra's neighbours; outlives this, and is attached to its
    *            complex before surface()
    * \param[in] positions, weights per vertex */
  DefaultSurface (const FilledInParallel<std::uint32_t>& tetrahedra, const Tetrahedra& adjacency,
                  const std::vector<Point3>& positions, const std::vector<double>& weights);
  DefaultSurface (const DefaultSurface&) = delete;
  DefaultSurface& operator= (const DefaultSurface&) = delete;
  /** \brief Waits for a flood still running (the engine stopped at an exception); its own
    * exception, if any, is dropped. */
  ~DefaultSurface ();

  /** \brief The surface in vertex ids: its triangles and, where they touch themselves or a
    * single layer is doubled, their split into a closed 2-manifold. */
  struct Output
  {
    Boundary w;
    std::optional<ManifoldSplit> split;
  };

  /** \brief The surface, once X is known; call once. Records the stages "labelling" and
    * "repair" (or "sheet") on \a clock and what it did in \a stats.
    * \param[in] positions per vertex
    * \param[in] closed a single layer as a closed two-sided shell rather than an open sheet
    * \param[in] viewpoint where an open sheet faces, if given (openSheet()) */
  Output surface (const Subcomplex& x, const std::vector<Point3>& positions, bool closed,
                  const std::optional<Point3>& viewpoint, WrapStatistics& stats, StageClock& clock);

private:
  const Tetrahedra& adjacency_;
  std::optional<SolidLabelling> labelling_; ///< engaged while its flood may run
  tbb::task_group flooding_;
};

} // namespace pcl_wrap::detail

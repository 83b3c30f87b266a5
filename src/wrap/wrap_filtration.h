// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "wrap/classification.h"
#include "delaunay/simplicial_complex.h"

#include <pcl_wrap/compute_wrap.h>

#include <array>
#include <limits>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The wrap filtration (docs/design.md §6): every sink deleted in order of decreasing size,
  * each deletion followed by a retraction, and every simplex given the size of the sink whose
  * deletion removed it. X(delta) = the simplices of finite value <= delta, for any delta, by a
  * filter.
  */
struct WrapFiltration
{
  /** \brief The sinks other than omega by decreasing size (exact order; equal sizes in
    * lexicographic order of their vertices' coordinates), and their sizes (squared radii of
    * their smallest orthospheres, rounded, non-increasing). */
  std::vector<Simplex> sinks;
  std::vector<double> sink_sizes;
  /** \brief The number of sinks other than omega, including those orderSinks() left out. */
  std::size_t sink_count = 0;
  /** \brief Per simplex: +inf when the basic construction (omega) removed it, the size of the
    * sink whose deletion removed it, or -inf when nothing did. */
  std::array<std::vector<double>, 4> value;
  /** \brief Sinks still present but not principal at their turn (the theory says none). */
  std::size_t not_principal = 0;
  std::size_t deletions = 0;

  /** \brief Is \a s in X(delta), kept by every deletion of a sink larger than delta? (+inf
    * values, removed by the basic construction, never are; delta = +inf gives the basic X.) */
  bool inX (Simplex s, double delta) const
  {
    return value[s.dim][s.id] <= delta && value[s.dim][s.id] < std::numeric_limits<double>::infinity ();
  }
};

/** \brief Orders the sinks of \a classification by decreasing size (vertex ids of \a complex
  * index \a positions and \a weights) into \a filtration: all of them, or only a prefix of that
  * order: the sinks larger than \a larger_than, and at least the \a at_least largest. Every size
  * is first bounded in interval arithmetic, on all threads; only the sinks that may belong to the
  * prefix are sized exactly and sorted. */
void
orderSinks (const SimplicialComplex& complex, const Classification& classification,
            const std::vector<Point3>& positions, const std::vector<double>& weights, WrapFiltration& filtration,
            double larger_than = -std::numeric_limits<double>::infinity (), std::size_t at_least = 0);

/** \brief The wrap filtration. \a order_seed as for Retraction::retract. */
WrapFiltration
wrapFiltration (const SimplicialComplex& complex, const Classification& classification,
                const std::vector<Point3>& positions, const std::vector<double>& weights,
                std::uint64_t order_seed = 0);

} // namespace pcl_wrap::detail

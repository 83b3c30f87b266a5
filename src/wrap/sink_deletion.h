// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "wrap/classification.h"
#include "wrap/retraction.h"
#include "delaunay/simplicial_complex.h"
#include "wrap/wrap_filtration.h"

#include <pcl_wrap/compute_wrap.h>

#include <cstddef>
#include <limits>

namespace pcl_wrap::detail
{

/** \brief Global deletion (docs/design.md §6), after \a retraction's first retraction: the sinks
  * of \a order in turn, while \a keep_going (rank, size) says so, each still-present one deleted
  * if principal and followed by a retraction; \a before (rank) is called before each deletion.
  * Returns how many were present but not principal. */
template <class KeepGoing, class Before>
std::size_t
deleteSinksGlobally (Retraction& retraction, const WrapFiltration& order, const KeepGoing& keep_going,
                     const Before& before, std::size_t& deleted, std::uint64_t order_seed = 0)
{
  std::size_t not_principal = 0;
  for (std::size_t j = 0; j < order.sinks.size () && keep_going (j, order.sink_sizes[j]); ++j)
  {
    if (!retraction.subcomplex ().contains (order.sinks[j]))
      continue; // an earlier retraction took it
    before (j);
    if (!retraction.deletePrincipal (order.sinks[j]))
    {
      ++not_principal;
      continue;
    }
    ++deleted;
    retraction.retractFreed (order_seed);
  }
  return not_principal;
}

/** \brief How many of the largest sink sizes WrapStatistics::largest_sinks holds. */
constexpr std::size_t LARGEST_SINKS_REPORTED = 10;

/** \brief The number of sinks and the largest sizes, from sinks in order, into \a stats. */
void
recordSinks (const WrapFiltration& order, WrapStatistics& stats);

/** \brief After the basic retraction of Del S to \a y: the sink deletion \a parameters ask for,
  * with its numbers in \a stats. \a ordered: the sinks already in order, or null. */
void
deleteSinks (const SimplicialComplex& complex, const Classification& classification,
             const std::vector<Point3>& positions, const std::vector<double>& weights,
             const WrapParameters& parameters, const WrapFiltration* ordered, Subcomplex& y, WrapStatistics& stats);

} // namespace pcl_wrap::detail

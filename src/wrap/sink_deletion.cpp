// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap/sink_deletion.h"

#include "wrap/front_deletion.h"

#include "delaunay/spacing.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_wrap::detail
{

void
recordSinks (const WrapFiltration& order, WrapStatistics& stats)
{
  stats.sinks = order.sink_count;
  stats.largest_sinks.assign (order.sink_sizes.begin (),
                              order.sink_sizes.begin () + std::min (LARGEST_SINKS_REPORTED, order.sink_sizes.size ()));
}

void
deleteSinks (const SimplicialComplex& complex, const Classification& classification,
             const std::vector<Point3>& positions, const std::vector<double>& weights,
             const WrapParameters& parameters, const WrapFiltration* ordered, Subcomplex& y, WrapStatistics& stats)
{
  if (stats.spacing == 0.0 && complex.size (1) != 0) // the engine has measured it already
    stats.spacing = medianNearestNeighbourDistance (complex.vertices (1, 0), complex.size (1), 1, positions);
  const Threshold& threshold = parameters.threshold;
  using Kind = Threshold::Kind;
  stats.delta = threshold.kind () == Kind::relative_radius ? std::pow (threshold.value () * stats.spacing, 2)
              : threshold.kind () == Kind::size         ? threshold.value ()
                                                        : std::numeric_limits<double>::infinity ();
  // Without the filtration, only the sinks a deletion may look at are ordered: those above
  // delta, or the count largest, and the largest few for the statistics.
  WrapFiltration own;
  if (!ordered)
    orderSinks (complex, classification, positions, weights, own, stats.delta,
                std::max (LARGEST_SINKS_REPORTED, threshold.kind () == Kind::largest ? threshold.count () : 0));
  const WrapFiltration& order = ordered ? *ordered : own;
  recordSinks (order, stats);

  if (parameters.deletion == SinkDeletion::global || threshold.kind () == Kind::largest)
  {
    const auto keep_going = [&] (std::size_t rank, double size) {
      return threshold.kind () == Kind::largest ? rank < threshold.count () : size > stats.delta;
    };
    Retraction retraction (y, classification);
    stats.sinks_not_principal =
        deleteSinksGlobally (retraction, order, keep_going, [] (std::size_t) {}, stats.sinks_deleted);
  }
  else
  {
    std::vector<std::uint8_t> in_front;
    if (parameters.region.shape != Region::Shape::everywhere)
      for (const Point3& p : positions)
        in_front.push_back (parameters.region.contains (p));
    const FrontDeletion front = deleteExposedSinks (y, classification, order, stats.delta, in_front);
    stats.sinks_deleted = front.deleted;
    stats.sinks_enclosed = front.enclosed;
    stats.sinks_not_principal = front.not_principal;
  }
}

} // namespace pcl_wrap::detail

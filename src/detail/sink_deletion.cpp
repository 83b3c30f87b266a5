// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "sink_deletion.h"

#include "front_deletion.h"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>

namespace pcl_wrap::detail
{

void
recordSinks (const WrapFiltration& order, WrapStatistics& stats)
{
  stats.sinks = order.sinks.size ();
  stats.largest_sinks.assign (order.sink_sizes.begin (),
                              order.sink_sizes.begin () + std::min<std::size_t> (10, order.sink_sizes.size ()));
}

void
deleteSinks (const SimplicialComplex& complex, const Classification& classification,
             const std::vector<Point3>& positions, const std::vector<double>& weights,
             const WrapParameters& parameters, const WrapFiltration* ordered, Retraction& y, WrapStatistics& stats)
{
  WrapFiltration own;
  if (!ordered)
    orderSinks (complex, classification, positions, weights, own);
  const WrapFiltration& order = ordered ? *ordered : own;
  recordSinks (order, stats);
  stats.spacing = pcl_wrap::medianSpacing (positions);
  stats.delta = parameters.radius_rel > 0 ? std::pow (parameters.radius_rel * stats.spacing, 2) : parameters.delta;

  if (parameters.deletion == SinkDeletion::global || parameters.sinks > 0)
  {
    const auto keep_going = [&] (std::size_t rank, double size) {
      return parameters.sinks > 0 ? rank < parameters.sinks : size > stats.delta;
    };
    stats.sinks_not_principal =
        deleteSinksGlobally (y, order, keep_going, [] (std::size_t) {}, stats.sinks_deleted);
  }
  else
  {
    std::vector<std::uint8_t> in_front;
    if (parameters.region.shape != Region::Shape::everywhere)
      for (const Point3& p : positions)
        in_front.push_back (parameters.region.contains (p));
    const FrontDeletion front = deleteExposedSinks (complex, y, order, stats.delta, in_front);
    stats.sinks_deleted = front.deleted;
    stats.sinks_enclosed = front.enclosed;
    stats.sinks_not_principal = front.not_principal;
  }
}

} // namespace pcl_wrap::detail

namespace pcl_wrap
{

double
medianSpacing (const std::vector<Point3>& positions)
{
  if (positions.size () < 2)
    return 0.0;
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  for (const Point3& p : positions)
    cloud->push_back (pcl::PointXYZ (float (p[0]), float (p[1]), float (p[2])));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud (cloud);
  std::vector<double> nearest;
  pcl::Indices neighbours (2);
  std::vector<float> squared (2);
  for (const auto& q : *cloud)
    if (tree.nearestKSearch (q, 2, neighbours, squared) == 2)
      nearest.push_back (std::sqrt (double (squared[1])));
  if (nearest.empty ())
    return 0.0;
  std::nth_element (nearest.begin (), nearest.begin () + nearest.size () / 2, nearest.end ());
  return nearest[nearest.size () / 2];
}

} // namespace pcl_wrap

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "delaunay/input_points.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pcl_wrap::detail
{

InputPoints
selectInputPoints (const std::vector<Point3>& points, const std::vector<double>& weights)
{
  if (!weights.empty () && weights.size () != points.size ())
    throw std::invalid_argument ("weights: one per point expected");
  const auto weight = [&] (PointIndex i) { return weights.empty () ? 0.0 : weights[i]; };

  InputPoints s;
  // Sorted with their coordinates and weights at hand, not through the indices: a comparison
  // then reads two neighbouring entries instead of two random points.
  struct Entry
  {
    Point3 position;
    double weight;
    PointIndex index;
  };
  std::vector<Entry> finite;
  finite.reserve (points.size ());
  for (PointIndex i = 0; i < points.size (); ++i)
  {
    const Point3& p = points[i];
    if (std::isfinite (p[0]) && std::isfinite (p[1]) && std::isfinite (p[2]) && std::isfinite (weight (i)))
      finite.push_back ({p, weight (i), i});
    else
      s.skipped.push_back (i);
  }

  // Equal positions become neighbours; among them the largest weight, then the smallest index,
  // comes first and is the one kept. -0.0 == 0.0 here, as it is for the geometry.
  tbb::parallel_sort (finite.begin (), finite.end (), keptBefore<Entry>);
  std::vector<bool> is_kept (points.size (), false);
  std::size_t last_kept = 0;
  for (std::size_t k = 0; k < finite.size (); ++k)
  {
    if (k > 0 && finite[k].position == finite[last_kept].position)
      s.duplicates.emplace_back (finite[k].index, finite[last_kept].index);
    else
      is_kept[finite[last_kept = k].index] = true;
  }
  finite = {};
  std::sort (s.duplicates.begin (), s.duplicates.end ());

  // Keep input order, so everything downstream is independent of the sort above.
  std::vector<PointIndex> kept;
  for (PointIndex i = 0; i < points.size (); ++i)
    if (is_kept[i])
      kept.push_back (i);

  s.positions.reserve (kept.size ());
  s.weights.reserve (kept.size ());
  for (PointIndex i : kept)
  {
    s.positions.push_back (points[i]);
    s.weights.push_back (weight (i));
  }
  s.input_index = std::move (kept);
  return s;
}

} // namespace pcl_wrap::detail

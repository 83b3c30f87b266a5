// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "delaunay/spacing.h"

#include "delaunay/input_points.h"
#include "util/parallel_for_each.h"
#include "util/portable.h"
#include "delaunay/regular_triangulation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_wrap::detail
{

std::vector<double>
nearestNeighbourSquared (const std::uint32_t* simplices, std::size_t count, int dimension,
                         const std::vector<Point3>& positions)
{
  constexpr double NONE = std::numeric_limits<double>::infinity ();
  std::vector<double> nearest (positions.size (), NONE);
  const auto offer = [&] (std::uint32_t v, double squared) {
    double seen = relaxedLoad (&nearest[v]);
    while (squared < seen && !relaxedCompareExchange (&nearest[v], seen, squared))
    {}
  };
  const auto k = static_cast<std::size_t> (dimension) + 1;
  parallelForEach (count, [&] (std::size_t s) {
    const std::uint32_t* v = simplices + k * s;
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t j = i + 1; j < k; ++j)
      {
        const Point3 &a = positions[v[i]], &b = positions[v[j]];
        const double squared =
            (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
        offer (v[i], squared);
        offer (v[j], squared);
      }
  });
  return nearest;
}

double
medianNearestNeighbourDistance (const std::uint32_t* simplices, std::size_t count, int dimension,
                                const std::vector<Point3>& positions)
{
  if (dimension < 1)
    return 0.0;
  constexpr double NONE = std::numeric_limits<double>::infinity ();
  std::vector<double> nearest = nearestNeighbourSquared (simplices, count, dimension, positions);
  nearest.erase (std::remove (nearest.begin (), nearest.end (), NONE), nearest.end ());
  if (nearest.empty ())
    return 0.0;
  std::nth_element (nearest.begin (), nearest.begin () + nearest.size () / 2, nearest.end ());
  return std::sqrt (nearest[nearest.size () / 2]);
}

} // namespace pcl_wrap::detail

namespace pcl_wrap
{

double
medianSpacing (const std::vector<Point3>& points)
{
  const detail::InputPoints input = detail::selectInputPoints (points, {}); // finite, distinct
  const detail::Triangulation t = detail::triangulate (input.positions, input.weights);
  std::vector<Point3> by_vertex (t.point_of_vertex.size ());
  for (std::size_t v = 0; v < by_vertex.size (); ++v)
    by_vertex[v] = input.positions[t.point_of_vertex[v]];
  const std::size_t count = t.dimension >= 1 ? t.top_simplices.size () / std::size_t (t.dimension + 1) : 0;
  return detail::medianNearestNeighbourDistance (t.top_simplices.data (), count, t.dimension, by_vertex);
}

} // namespace pcl_wrap

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/points_apart.h"

#include "util/distance.h"
#include "util/union_find.h"

#include <algorithm>
#include <limits>

namespace pcl_wrap::detail
{

std::vector<std::uint8_t>
pointsApart (const SimplicialComplex& complex, const std::vector<Point3>& positions)
{
  const std::uint32_t n = complex.numVertices ();
  const SimplexId edges = complex.size (1);
  if (n < 5)
    return {};
  const auto length = [&] (SimplexId e) {
    return distance (positions[complex.vertex (1, e, 0)], positions[complex.vertex (1, e, 1)]);
  };
  // Each point's nearest neighbour, one of its Delaunay neighbours; the sample's median spacing.
  std::vector<double> nearest (n, std::numeric_limits<double>::infinity ());
  for (SimplexId e = 0; e < edges; ++e)
  {
    const std::uint32_t a = complex.vertex (1, e, 0), b = complex.vertex (1, e, 1);
    const double d = length (e);
    nearest[a] = std::min (nearest[a], d);
    nearest[b] = std::min (nearest[b], d);
  }
  std::vector<double> spacings (nearest);
  const auto middle = spacings.begin () + std::ptrdiff_t (n / 2);
  std::nth_element (spacings.begin (), middle, spacings.end ());
  const double far = APART_SPACINGS * *middle;
  std::vector<double> ().swap (spacings);
  // Groups of points tied by edges no longer than that, far at the scale of the whole sample (a
  // mesh's vertices, sparse on its flat parts, can be far apart at the scale of some of their
  // neighbours). A point in a group of at most APART_CLUSTER has at most that many less one such
  // edges: where none has, as in every sample of a surface, there is nothing more to look at.
  std::vector<std::uint8_t> ties (n, 0);
  for (SimplexId e = 0; e < edges; ++e)
    if (length (e) <= far)
      for (int k = 0; k < 2; ++k)
      {
        std::uint8_t& t = ties[complex.vertex (1, e, k)];
        t = std::uint8_t (std::min (t + 1, 255));
      }
  if (std::none_of (ties.begin (), ties.end (), [] (std::uint8_t t) { return t < APART_CLUSTER; }))
    return {};
  UnionFind groups (n);
  for (SimplexId e = 0; e < edges; ++e)
  {
    const std::uint32_t a = groups.find (complex.vertex (1, e, 0)), b = groups.find (complex.vertex (1, e, 1));
    if (a != b && length (e) <= far)
      groups.attach (a, b);
  }
  std::vector<std::uint32_t> size (n, 0);
  for (std::uint32_t v = 0; v < n; ++v)
    ++size[groups.find (v)];
  const auto small = [&] (std::uint32_t v) { return size[groups.find (v)] <= APART_CLUSTER; };
  // Per point of a small group: its distance to the nearest point outside, its Delaunay neighbours
  // outside, and those of them more than APART_SPACINGS times nearer their own nearest point.
  std::vector<double> out (n, std::numeric_limits<double>::infinity ());
  std::vector<std::uint32_t> outside (n, 0), denser (n, 0);
  for (int pass = 0; pass < 2; ++pass)
    for (SimplexId e = 0; e < edges; ++e)
    {
      const std::uint32_t a = complex.vertex (1, e, 0), b = complex.vertex (1, e, 1);
      if (groups.find (a) == groups.find (b))
        continue;
      for (const auto& [v, w] : {std::pair (a, b), std::pair (b, a)})
      {
        if (!small (v))
          continue;
        if (pass == 0)
          out[v] = std::min (out[v], length (e));
        else
        {
          ++outside[v];
          denser[v] += APART_SPACINGS * nearest[w] < out[v];
        }
      }
    }
  std::vector<std::uint8_t> apart (n, 0);
  bool any = false;
  for (std::uint32_t v = 0; v < n; ++v)
  {
    apart[v] = small (v) && 4 * denser[v] > 3 * outside[v];
    any = any || apart[v];
  }
  return any ? apart : std::vector<std::uint8_t> ();
}

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/points_apart.h"

#include "util/distance.h"

#include <algorithm>
#include <limits>

namespace pcl_wrap::detail
{

std::vector<std::uint8_t>
pointsApart (const SimplicialComplex& complex, const std::vector<Point3>& positions)
{
  const std::uint32_t n = complex.numVertices ();
  const SimplexId edges = complex.size (1);
  std::vector<std::uint8_t> apart (n, 0);
  if (n < 5)
    return apart;
  // Each point's nearest neighbour: one of its Delaunay neighbours.
  std::vector<double> nearest (n, std::numeric_limits<double>::infinity ());
  for (SimplexId e = 0; e < edges; ++e)
  {
    const std::uint32_t a = complex.vertex (1, e, 0), b = complex.vertex (1, e, 1);
    const double d = distance (positions[a], positions[b]);
    nearest[a] = std::min (nearest[a], d);
    nearest[b] = std::min (nearest[b], d);
  }
  // Per point, its Delaunay neighbours, and those of them much nearer their own nearest point.
  std::vector<std::uint32_t> neighbours (n, 0), dense (n, 0);
  for (SimplexId e = 0; e < edges; ++e)
  {
    const std::uint32_t a = complex.vertex (1, e, 0), b = complex.vertex (1, e, 1);
    ++neighbours[a];
    ++neighbours[b];
    dense[a] += APART_SPACINGS * nearest[b] < nearest[a];
    dense[b] += APART_SPACINGS * nearest[a] < nearest[b];
  }
  // And far at the scale of the whole sample: a mesh's vertices, sparse on its flat parts, can be
  // far apart at the scale of some of their neighbours.
  std::vector<double> spacings (nearest);
  const auto middle = spacings.begin () + std::ptrdiff_t (n / 2);
  std::nth_element (spacings.begin (), middle, spacings.end ());
  const double far = APART_SPACINGS * *middle;
  for (std::uint32_t v = 0; v < n; ++v)
    apart[v] = 4 * dense[v] > 3 * neighbours[v] && nearest[v] > far;
  return apart;
}

} // namespace pcl_wrap::detail

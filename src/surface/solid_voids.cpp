// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_voids.h"

#include "surface/solid_join.h"
#include "util/parallel_for_each.h"

#include <algorithm>
#include <utility>

namespace pcl_wrap::detail
{

std::vector<std::uint32_t>
fillUnsampledVoids (const Tetrahedra& tetrahedra, SolidLabels& labels, std::vector<std::uint8_t>& moved)
{
  const std::size_t n = tetrahedra.size ();
  std::vector<std::uint8_t> outside (n);
  parallelForEach (n, [&] (std::size_t t) { outside[t] = !labels.inside[t]; });
  const SolidParts parts = solidParts (tetrahedra, outside);
  // A part reaching the hull is the outside; the others are voids, most of them a few tetrahedra.
  std::vector<std::uint8_t> open (parts.size.size (), 0);
  for (std::uint32_t t = 0; t < n; ++t)
    if (outside[t])
      for (int i = 0; i < 4; ++i)
        if (tetrahedra.neighbour (t, i) == OUTSIDE_HULL)
          open[parts.part[t]] = 1;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> corners; // (void, vertex)
  for (std::uint32_t t = 0; t < n; ++t)
    if (outside[t] && !open[parts.part[t]])
      for (int i = 0; i < 4; ++i)
        corners.emplace_back (parts.part[t], tetrahedra.vertex (t, i));
  std::sort (corners.begin (), corners.end ());
  corners.erase (std::unique (corners.begin (), corners.end ()), corners.end ());
  std::vector<std::uint32_t> vertices (parts.size.size (), 0);
  for (const auto& c : corners)
    ++vertices[c.first];
  std::vector<std::uint32_t> filled;
  for (std::uint32_t t = 0; t < n; ++t)
    if (outside[t] && !open[parts.part[t]] && vertices[parts.part[t]] < FRAGMENT_VERTICES)
    {
      labels.inside[t] = 1;
      moved[t] = 1;
      filled.push_back (t);
    }
  return filled;
}

} // namespace pcl_wrap::detail

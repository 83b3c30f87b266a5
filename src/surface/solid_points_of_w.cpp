// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_points_of_w.h"

#include "surface/solid_join.h"
#include "util/parallel_for_each.h"
#include "util/portable.h"

namespace pcl_wrap::detail
{

namespace
{

/** Rounds of moves: a point that a move brings on can open the way for a point next to it. */
constexpr int MAX_ROUNDS = 8;

/** One round: moves at most one tetrahedron per point (appended to \a moved); returns how many. */
std::size_t
bringOnOnce (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
             SolidLabels& labels, std::vector<std::uint32_t>& moved)
{
  // Per vertex: is it on W (a tetrahedron around it not in X, or a hull facet at it), and has it
  // a tetrahedron inside the solid, and one outside (or a hull facet of an inside one at it)?
  const std::uint32_t nv = tetrahedra.complex ().numVertices ();
  std::vector<std::uint8_t> on_w (nv, 0), has_inside (nv, 0), has_outside (nv, 0);
  parallelForEach (tetrahedra.size (), [&] (std::size_t t) { // stores of 1 from several threads
    const auto u = static_cast<std::uint32_t> (t);
    const bool inside = labels.inside[t] != 0, in_x = x.contains ({3, static_cast<SimplexId> (t)});
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t v = tetrahedra.vertex (u, i);
      relaxedStore (inside ? &has_inside[v] : &has_outside[v], std::uint8_t (1));
      if (!in_x)
        relaxedStore (&on_w[v], std::uint8_t (1));
      if (tetrahedra.neighbour (u, i) == OUTSIDE_HULL)
        for (int j = 1; j < 4; ++j)
        {
          const std::uint32_t w = tetrahedra.vertex (u, (i + j) & 3);
          relaxedStore (&on_w[w], std::uint8_t (1));
          if (inside)
            relaxedStore (&has_outside[w], std::uint8_t (1));
        }
    }
  });
  const std::size_t before = moved.size ();
  Star star;
  for (std::uint32_t v = 0; v < nv; ++v)
  {
    if (!on_w[v] || (has_inside[v] && has_outside[v]))
      continue;
    if (tetrahedra.tetrahedronOf (v) == NO_TETRAHEDRON)
      continue;
    tetrahedra.gatherStar (v, star);
    std::uint32_t best = OUTSIDE_HULL;
    double shortest = 0;
    for (std::uint32_t t : star.tetrahedra ())
    {
      int apex = 0;
      while (tetrahedra.vertex (t, apex) != v)
        ++apex;
      const std::uint32_t u = tetrahedra.neighbour (t, apex);
      // The facet opposite v is on the surface: across it, the other side (or the hull, outside).
      const bool across_inside = u != OUTSIDE_HULL && labels.inside[u];
      if (across_inside == (labels.inside[t] != 0))
        continue;
      const double longest = longestEdge (tetrahedra, positions, t);
      if (best == OUTSIDE_HULL || longest < shortest)
      {
        best = t;
        shortest = longest;
      }
    }
    if (best == OUTSIDE_HULL)
      continue;
    labels.inside[best] = !labels.inside[best];
    moved.push_back (best);
  }
  return moved.size () - before;
}

} // namespace

std::vector<std::uint32_t>
bringPointsOfWOn (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
                  SolidLabels& labels)
{
  std::vector<std::uint32_t> moved;
  for (int round = 0; round < MAX_ROUNDS && bringOnOnce (tetrahedra, x, positions, labels, moved) > 0; ++round)
  {}
  return moved;
}

} // namespace pcl_wrap::detail

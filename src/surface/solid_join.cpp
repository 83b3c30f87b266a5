// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_join.h"

#include "util/parallel_for_each.h"
#include "util/union_find.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

/** Is tetrahedron \a t in X, or one of its triangles? */
bool
inX (const Tetrahedra& tetrahedra, const Subcomplex& x, std::uint32_t t)
{
  if (x.contains ({3, t}))
    return true;
  for (int i = 0; i < 4; ++i)
    if (x.contains (tetrahedra.complex ().facet (3, t, i)))
      return true;
  return false;
}

} // namespace

SolidParts
solidParts (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside)
{
  const std::size_t n = tetrahedra.size ();
  UnionFind sets;
  sets.resetInParallel (n);
  parallelForEach (n, [&] (std::size_t id) {
    const auto t = static_cast<std::uint32_t> (id);
    if (!inside[t])
      return;
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = tetrahedra.neighbour (t, i);
      if (u != OUTSIDE_HULL && u > t && inside[u])
        sets.uniteConcurrently (t, u);
    }
  });
  SolidParts parts;
  parts.part.assign (n, SolidParts::NO_PART);
  for (std::uint32_t t = 0; t < n; ++t)
    if (inside[t] && sets.isRoot (t))
    {
      parts.part[t] = static_cast<std::uint32_t> (parts.size.size ());
      parts.size.push_back (0);
    }
  parallelForEach (n, [&] (std::size_t t) {
    const std::uint32_t r = inside[t] ? sets.findConcurrently (static_cast<std::uint32_t> (t)) : SolidParts::NO_PART;
    if (r != SolidParts::NO_PART && r != t)
      parts.part[t] = parts.part[r];
  });
  for (std::uint32_t t = 0; t < n; ++t)
    if (parts.part[t] != SolidParts::NO_PART)
      ++parts.size[parts.part[t]];
  return parts;
}

std::vector<std::uint32_t>
joinPartsThroughX (const Tetrahedra& tetrahedra, const Subcomplex& x, SolidLabels& labels,
                   std::vector<std::uint8_t>& moved_flags)
{
  constexpr std::uint32_t NONE = SolidParts::NO_PART;
  const std::size_t n = tetrahedra.size ();
  const SolidParts parts = solidParts (tetrahedra, labels.inside);
  const std::vector<std::uint32_t>& part = parts.part;
  std::vector<std::uint32_t> moved;
  if (parts.size.size () < 2)
    return moved;
  UnionFind joined (parts.size.size ());
  std::vector<std::uint32_t> order (parts.size.size ());
  std::iota (order.begin (), order.end (), 0u);
  std::stable_sort (order.begin (), order.end (),
                    [&] (std::uint32_t a, std::uint32_t b) { return parts.size[a] < parts.size[b]; });
  order.pop_back (); // the largest part stays as it is
  std::vector<std::vector<std::uint32_t>> members (parts.size.size ());
  for (std::uint32_t t = 0; t < n; ++t)
    if (part[t] != NONE)
      members[part[t]].push_back (t);
  std::vector<double> cost (n, std::numeric_limits<double>::infinity ());
  std::vector<std::uint32_t> from (n, NONE), reached;
  using Entry = std::pair<double, std::uint32_t>;
  for (std::uint32_t p : order)
  {
    const std::uint32_t mine = joined.find (p);
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::uint32_t t : members[p])
    {
      cost[t] = 0;
      reached.push_back (t);
      queue.push ({0.0, t});
    }
    std::uint32_t goal = NONE;
    while (!queue.empty () && goal == NONE)
    {
      const auto [c, a] = queue.top ();
      queue.pop ();
      if (c > cost[a])
        continue;
      for (int i = 0; i < 4 && goal == NONE; ++i)
      {
        const std::uint32_t b = tetrahedra.neighbour (a, i);
        if (b == OUTSIDE_HULL)
          continue;
        if (labels.inside[b])
        {
          if (part[b] != NONE && joined.find (part[b]) != mine)
          {
            goal = b;
            from[b] = a;
          }
          continue;
        }
        const double through = c + labels.margin[b];
        if (!inX (tetrahedra, x, b) || through >= cost[b])
          continue;
        if (cost[b] == std::numeric_limits<double>::infinity ())
          reached.push_back (b);
        cost[b] = through;
        from[b] = a;
        queue.push ({through, b});
      }
    }
    if (goal != NONE)
    {
      joined.attach (mine, part[goal]);
      for (std::uint32_t t = from[goal]; !labels.inside[t]; t = from[t])
      {
        labels.inside[t] = 1;
        moved_flags[t] = 1;
        moved.push_back (t);
      }
    }
    for (std::uint32_t t : reached)
    {
      cost[t] = std::numeric_limits<double>::infinity ();
      from[t] = NONE;
    }
    reached.clear ();
  }
  return moved;
}

} // namespace pcl_wrap::detail

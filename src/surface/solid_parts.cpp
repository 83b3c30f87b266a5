// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_parts.h"

#include "util/parallel_for_each.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>

namespace pcl_wrap::detail
{
namespace
{

/** How many inside tetrahedra staysOnePart() searches around a cluster of changes, at most: far
  * more than a way round a few moved tetrahedra takes. */
constexpr std::size_t LOCAL_REACH = 4096;

} // namespace

SideParts::SideParts (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside, Sides sides)
  : tetrahedra_ (tetrahedra)
{
  const std::size_t n = tetrahedra.size ();
  sets_.resetInParallel (n);
  parallelForEach (n, [&] (std::size_t id) {
    const auto t = static_cast<std::uint32_t> (id);
    if ((sides == Sides::outside && inside[t]) || (sides == Sides::solid && !inside[t]))
      return;
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = tetrahedra.neighbour (t, i);
      if (u != OUTSIDE_HULL && u > t && inside[u] == inside[t])
        sets_.uniteConcurrently (t, u);
    }
  });
}

void
SideParts::movedInside (const std::vector<std::uint32_t>& moved)
{
  // A whole part of the outside moved: its tetrahedra's neighbours are its own or inside.
  for (std::uint32_t t : moved)
    for (int i = 0; i < 4; ++i)
      if (tetrahedra_.neighbour (t, i) != OUTSIDE_HULL)
        sets_.uniteConcurrently (t, tetrahedra_.neighbour (t, i));
}

SolidParts
SideParts::solid (const std::vector<std::uint8_t>& inside)
{
  const std::size_t n = tetrahedra_.size ();
  SolidParts parts;
  parts.part.assign (n, SolidParts::NO_PART);
  const std::vector<std::uint32_t> roots =
      indicesWhere (n, [&] (std::size_t t) { return inside[t] && sets_.isRoot (static_cast<std::uint32_t> (t)); });
  for (std::uint32_t k = 0; k < roots.size (); ++k)
    parts.part[roots[k]] = k;
  tbb::enumerable_thread_specific<std::vector<std::uint32_t>> sizes (std::vector<std::uint32_t> (roots.size (), 0));
  tbb::parallel_for (tbb::blocked_range<std::size_t> (0, n, 4096), [&] (const tbb::blocked_range<std::size_t>& r) {
    std::vector<std::uint32_t>& local = sizes.local (); // once a chunk: a lookup costs as much as a find
    for (std::size_t t = r.begin (); t != r.end (); ++t)
    {
      if (!inside[t])
        continue;
      const std::uint32_t root = sets_.findConcurrently (static_cast<std::uint32_t> (t));
      const std::uint32_t p = parts.part[root]; // a root's own entry, set above
      ++local[p];
      if (root != t)
        parts.part[t] = p;
    }
  });
  parts.size.assign (roots.size (), 0);
  for (const std::vector<std::uint32_t>& local : sizes)
    for (std::size_t k = 0; k < local.size (); ++k)
      parts.size[k] += local[k];
  return parts;
}

SolidParts
solidParts (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside)
{
  return SideParts (tetrahedra, inside, SideParts::Sides::solid).solid (inside);
}

bool
staysOnePart (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& after,
              const std::vector<std::uint32_t>& changed)
{
  const auto indexOf = [&] (std::uint32_t t) { // in changed, or changed.size ()
    const auto at = std::lower_bound (changed.begin (), changed.end (), t);
    return at != changed.end () && *at == t ? std::size_t (at - changed.begin ()) : changed.size ();
  };
  std::vector<std::uint8_t> clustered (changed.size (), 0);
  std::vector<std::uint32_t> cluster, touching, queue;
  std::vector<std::uint32_t> reached (tetrahedra.size (), 0); // per tetrahedron, the last cluster to reach it
  std::uint32_t stamp = 0;
  for (std::size_t k = 0; k < changed.size (); ++k)
  {
    if (clustered[k])
      continue;
    // The cluster of changes through k, and the tetrahedra inside after in it or next to it.
    cluster.assign (1, changed[k]);
    clustered[k] = 1;
    touching.clear ();
    bool kept_next_to_it = false;
    for (std::size_t c = 0; c < cluster.size (); ++c)
    {
      const std::uint32_t t = cluster[c];
      if (after[t])
        touching.push_back (t);
      for (int i = 0; i < 4; ++i)
      {
        const std::uint32_t u = tetrahedra.neighbour (t, i);
        if (u == OUTSIDE_HULL)
          continue;
        const std::size_t j = indexOf (u);
        if (j == changed.size ())
        {
          if (after[u]) // and so before: it did not change
          {
            touching.push_back (u);
            kept_next_to_it = true;
          }
        }
        else if (!clustered[j])
        {
          clustered[j] = 1;
          cluster.push_back (u);
        }
      }
    }
    if (!kept_next_to_it)
      return false;
    // Are they connected through the solid after, nearby?
    std::sort (touching.begin (), touching.end ());
    touching.erase (std::unique (touching.begin (), touching.end ()), touching.end ());
    reached[touching[0]] = ++stamp;
    queue.assign (1, touching[0]); // breadth first: the way round is near
    std::size_t found = 1;
    for (std::size_t q = 0; found < touching.size () && q < queue.size () && queue.size () < LOCAL_REACH; ++q)
    {
      const std::uint32_t t = queue[q];
      for (int i = 0; i < 4; ++i)
      {
        const std::uint32_t u = tetrahedra.neighbour (t, i);
        if (u == OUTSIDE_HULL || !after[u] || reached[u] == stamp)
          continue;
        reached[u] = stamp;
        queue.push_back (u);
        found += std::binary_search (touching.begin (), touching.end (), u);
      }
    }
    if (found < touching.size ())
      return false;
  }
  return true;
}

} // namespace pcl_wrap::detail

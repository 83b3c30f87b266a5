// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_voids.h"

#include "surface/solid_join.h"
#include "util/parallel_for_each.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <unordered_map>
#include <utility>

namespace pcl_wrap::detail
{

std::vector<std::uint32_t>
fillUnsampledVoids (const Tetrahedra& tetrahedra, SolidLabels& labels, std::vector<std::uint8_t>& moved)
{
  SideParts sides (tetrahedra, labels.inside, SideParts::Sides::outside);
  return fillUnsampledVoids (tetrahedra, labels, moved, sides);
}

namespace
{

/** The tetrahedra outside the solid \a inside in a part of the outside that does not reach the
  * convex hull (\a sides: the parts of the outside, or of both sides): the voids', ascending. */
std::vector<std::uint32_t>
tetrahedraInVoids (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside, SideParts& sides)
{
  const std::size_t n = tetrahedra.size ();
  // A part reaching the hull is the outside; the others are voids, most of them a few tetrahedra.
  std::unique_ptr<std::atomic<std::uint8_t>[]> open (new std::atomic<std::uint8_t>[n]());
  parallelForEach (n, [&] (std::size_t t) {
    if (!inside[t] && tetrahedra.onHull (static_cast<std::uint32_t> (t)))
      open[sides.part (static_cast<std::uint32_t> (t))].store (1, std::memory_order_relaxed);
  });
  return indicesWhere (n, [&] (std::size_t t) {
    return !inside[t] && !open[sides.part (static_cast<std::uint32_t> (t))].load (std::memory_order_relaxed);
  });
}

} // namespace

std::vector<std::uint32_t>
fillUnsampledVoids (const Tetrahedra& tetrahedra, SolidLabels& labels, std::vector<std::uint8_t>& moved,
                    SideParts& sides, std::vector<std::uint32_t>* kept)
{
  const std::vector<std::uint32_t> in_voids = tetrahedraInVoids (tetrahedra, labels.inside, sides);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> corners; // (void, vertex)
  for (std::uint32_t t : in_voids)
    for (int i = 0; i < 4; ++i)
      corners.emplace_back (sides.part (t), tetrahedra.vertex (t, i));
  std::sort (corners.begin (), corners.end ());
  corners.erase (std::unique (corners.begin (), corners.end ()), corners.end ());
  std::unordered_map<std::uint32_t, std::uint32_t> vertices; // per void
  for (const auto& c : corners)
    ++vertices[c.first];
  std::vector<std::uint32_t> filled;
  for (std::uint32_t t : in_voids)
    if (vertices[sides.part (t)] < FRAGMENT_VERTICES)
    {
      labels.inside[t] = 1;
      moved[t] = 1;
      filled.push_back (t);
    }
    else if (kept)
      kept->push_back (t);
  sides.movedInside (filled);
  return filled;
}

std::vector<std::uint32_t>
fillUnsampledVoidsNear (const Tetrahedra& tetrahedra, SolidLabels& labels, std::vector<std::uint8_t>& moved,
                        const std::vector<std::uint32_t>& changed)
{
  std::vector<std::uint32_t> seeds;
  for (std::uint32_t t : changed)
  {
    seeds.push_back (t);
    for (int i = 0; i < 4; ++i)
      if (tetrahedra.neighbour (t, i) != OUTSIDE_HULL)
        seeds.push_back (tetrahedra.neighbour (t, i));
  }
  std::sort (seeds.begin (), seeds.end ());
  seeds.erase (std::unique (seeds.begin (), seeds.end ()), seeds.end ());
  // From each seed outside, the outside tetrahedra connected to it, until they reach the hull, a
  // part found before to be large, or FRAGMENT_VERTICES vertices: then they are the outside or a
  // void the points show.
  enum : std::uint8_t
  {
    UNSEEN,
    SEARCHED,
    LARGE
  };
  std::vector<std::uint8_t> state (tetrahedra.size (), UNSEEN);
  std::vector<std::uint32_t> filled, part, stack, corners;
  for (std::uint32_t seed : seeds)
  {
    if (labels.inside[seed] || state[seed] != UNSEEN)
      continue;
    part.clear ();
    corners.clear ();
    stack.assign (1, seed);
    state[seed] = SEARCHED;
    bool small = true;
    while (small && !stack.empty ())
    {
      const std::uint32_t t = stack.back ();
      stack.pop_back ();
      part.push_back (t);
      for (int i = 0; i < 4; ++i)
        if (std::find (corners.begin (), corners.end (), tetrahedra.vertex (t, i)) == corners.end ())
          corners.push_back (tetrahedra.vertex (t, i));
      small = corners.size () < FRAGMENT_VERTICES;
      for (int i = 0; small && i < 4; ++i)
      {
        const std::uint32_t u = tetrahedra.neighbour (t, i);
        small = u != OUTSIDE_HULL && state[u] != LARGE;
        if (small && !labels.inside[u] && state[u] == UNSEEN)
        {
          state[u] = SEARCHED;
          stack.push_back (u);
        }
      }
    }
    if (small)
      filled.insert (filled.end (), part.begin (), part.end ());
    else
      for (const std::vector<std::uint32_t>* list : {&part, &stack})
        for (std::uint32_t t : *list)
          state[t] = LARGE;
  }
  std::sort (filled.begin (), filled.end ());
  for (std::uint32_t t : filled)
  {
    labels.inside[t] = 1;
    moved[t] = 1;
  }
  return filled;
}

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_join.h"

#include "util/distance.h"
#include "util/parallel_for_each.h"
#include "util/union_find.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

/** A join may close a gap up to this many times the spacing at its ends: one the sampling does not
  * resolve. Parts cut apart by the labelling lie within 1.1 spacings of each other; separate
  * objects, as close as two spacings, are apart. */
constexpr double UNRESOLVED_GAP = 1.5;

/** The points a join would tie together, and how far apart they are. */
class JoinGaps
{
public:
  JoinGaps (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions, const std::vector<std::uint32_t>& part)
    : tetrahedra_ (tetrahedra), positions_ (positions), part_ (part)
  {}

  /** Is the gap between part \a p and part \a q along the tetrahedra of \a chain no wider than
    * UNRESOLVED_GAP spacings: some vertex of p on the chain as near some vertex of q on it, in
    * units of the smaller of their spacings (the shortest Delaunay edge at each: a lone point of a
    * coarse sample has a long one)? */
  bool unresolved (const std::vector<std::uint32_t>& chain, std::uint32_t p, std::uint32_t q)
  {
    const std::vector<std::uint32_t> corners = tetrahedra_.verticesOf (chain);
    std::vector<std::pair<std::uint32_t, double>> on_p, on_q; // (vertex, its spacing)
    for (std::uint32_t v : corners)
    {
      // One look at v's star: whether it is on p or q, and its shortest Delaunay edge.
      tetrahedra_.gatherStar (v, star_);
      bool in_p = false, in_q = false;
      double spacing = std::numeric_limits<double>::infinity ();
      for (std::uint32_t t : star_.tetrahedra ())
      {
        in_p = in_p || part_[t] == p;
        in_q = in_q || part_[t] == q;
        for (int i = 0; i < 4; ++i)
          if (tetrahedra_.vertex (t, i) != v)
            spacing = std::min (spacing, distance (positions_[v], positions_[tetrahedra_.vertex (t, i)]));
      }
      if (in_p)
        on_p.emplace_back (v, spacing);
      if (in_q)
        on_q.emplace_back (v, spacing);
    }
    for (const auto& [a, spacing_a] : on_p)
      for (const auto& [b, spacing_b] : on_q)
        if (distance (positions_[a], positions_[b]) <= UNRESOLVED_GAP * std::min (spacing_a, spacing_b))
          return true;
    return false;
  }

private:
  const Tetrahedra& tetrahedra_;
  const std::vector<Point3>& positions_;
  const std::vector<std::uint32_t>& part_;
  Star star_;
};

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
joinPartsThroughX (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
                   SolidLabels& labels, std::vector<std::uint8_t>& moved_flags)
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
  JoinGaps gaps (tetrahedra, positions, part);
  std::vector<std::uint8_t> on_part (tetrahedra.complex ().numVertices (), 0);
  std::vector<std::uint32_t> chain;
  std::vector<double> cost (n, std::numeric_limits<double>::infinity ());
  std::vector<std::uint32_t> from (n, NONE), reached;
  using Entry = std::pair<double, std::uint32_t>;
  for (std::uint32_t p : order)
  {
    const std::uint32_t mine = joined.find (p);
    const std::vector<std::uint32_t> corners = tetrahedra.verticesOf (members[p]);
    const bool fragment = corners.size () < FRAGMENT_VERTICES;
    // A part of its own may only close a gap at its surface: its search stays among the
    // tetrahedra that touch it.
    for (std::uint32_t v : corners)
      on_part[v] = !fragment;
    const auto touches = [&] (std::uint32_t t) {
      const std::uint32_t* v = tetrahedra.vertices (t);
      return on_part[v[0]] || on_part[v[1]] || on_part[v[2]] || on_part[v[3]];
    };
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
          if (part[b] == NONE || joined.find (part[b]) == mine)
            continue;
          // A fragment joins the part it reaches first; a part of its own only one it was cut
          // from, across a gap the sampling does not resolve.
          chain.assign (1, b);
          for (std::uint32_t t = a;; t = from[t])
          {
            chain.push_back (t);
            if (labels.inside[t])
              break;
          }
          if (fragment || gaps.unresolved (chain, p, part[b]))
          {
            goal = b;
            from[b] = a;
          }
          continue;
        }
        const double through = c + labels.margin[b];
        if (!inX (tetrahedra, x, b) || through >= cost[b] || (!fragment && !touches (b)))
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
    for (std::uint32_t v : corners)
      on_part[v] = 0;
  }
  return moved;
}

} // namespace pcl_wrap::detail

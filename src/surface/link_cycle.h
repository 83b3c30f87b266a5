// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief What the edges of a vertex's link make: the edges opposite the vertex in its triangles. */
struct LinkShape
{
  std::uint32_t parts = 0; ///< connected parts, edges joined where they share an end
  bool cycles = true;      ///< every end on exactly two edges: each part is a cycle
};

/** \brief The shape of the \a k edges edge(0), ..., edge(k - 1), each a pair of vertex ids. A vertex
  * of a closed 2-manifold has one cycle; where the surface touches itself at the vertex, there is
  * one cycle per fan of triangles; where an edge at it has more than two triangles, two cycles
  * share an end. If \a part_of is given, part_of[e] is set to one edge of edge e's part, the same
  * for the whole part. */
template <class Edge>
LinkShape
linkShape (std::size_t k, const Edge& edge, std::uint32_t* part_of = nullptr)
{
  // (end, edge) for both ends of every edge, sorted, and a union-find over the edges.
  constexpr std::size_t ON_STACK = 32;
  std::array<std::pair<std::uint32_t, std::uint32_t>, 2 * ON_STACK> small_ends;
  std::array<std::uint32_t, ON_STACK> small_parent;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> large_ends;
  std::vector<std::uint32_t> large_parent;
  std::pair<std::uint32_t, std::uint32_t>* ends = small_ends.data ();
  std::uint32_t* parent = small_parent.data ();
  if (k > ON_STACK)
  {
    large_ends.resize (2 * k);
    large_parent.resize (k);
    ends = large_ends.data ();
    parent = large_parent.data ();
  }
  for (std::size_t e = 0; e < k; ++e)
  {
    const auto [a, b] = edge (e);
    ends[2 * e] = {a, static_cast<std::uint32_t> (e)};
    ends[2 * e + 1] = {b, static_cast<std::uint32_t> (e)};
    parent[e] = static_cast<std::uint32_t> (e);
  }
  std::sort (ends, ends + 2 * k);
  const auto root = [&] (std::uint32_t e) {
    while (parent[e] != e)
      e = parent[e] = parent[parent[e]];
    return e;
  };
  LinkShape shape{static_cast<std::uint32_t> (k), true};
  for (std::size_t a = 0, b = 0; a < 2 * k; a = b)
  {
    for (b = a + 1; b < 2 * k && ends[b].first == ends[a].first; ++b)
    {
      const std::uint32_t p = root (ends[a].second), q = root (ends[b].second);
      if (p != q)
      {
        parent[p] = q;
        --shape.parts;
      }
    }
    shape.cycles = shape.cycles && b - a == 2;
  }
  if (part_of)
    for (std::size_t e = 0; e < k; ++e)
      part_of[e] = root (static_cast<std::uint32_t> (e));
  return shape;
}

/** \brief Do the \a k edges edge(0), ..., edge(k - 1) make one short cycle, found by a walk round
  * it from the first edge, on to the one other edge at each end it reaches? True says they make
  * one cycle; false says only that the walk met something else (two cycles, an end on more than
  * two edges, more than SHORT edges), which linkShape() then tells. Most links of a surface are
  * one short cycle, and the walk says so without sorting. */
template <class Edge>
bool
isOneShortCycle (std::size_t k, const Edge& edge)
{
  constexpr std::size_t SHORT = 16;
  if (k < 3 || k > SHORT)
    return false;
  std::size_t at = 0;
  std::uint32_t end = edge (0).second;
  for (std::size_t steps = 1; steps <= k && edge (at).first != edge (at).second; ++steps)
  {
    std::size_t next = k, found = 0;
    for (std::size_t f = 0; f < k; ++f)
      if (f != at && (edge (f).first == end || edge (f).second == end))
      {
        next = f;
        ++found;
      }
    if (found != 1)
      return false;
    if (next == 0)
      return steps == k;
    at = next;
    end = edge (at).first == end ? edge (at).second : edge (at).first;
  }
  return false;
}

/** \brief Do the edges [first, last) (pairs of vertex ids) make one cycle, each vertex on it in
  * exactly two of them? A vertex of a closed 2-manifold has such a link. */
template <class It>
bool
isOneCycle (It first, It last)
{
  const auto k = static_cast<std::size_t> (last - first);
  if (k < 3)
    return false;
  const auto edge = [&] (std::size_t e) { return std::make_pair (first[e][0], first[e][1]); };
  if (isOneShortCycle (k, edge))
    return true;
  const LinkShape shape = linkShape (k, edge);
  return shape.cycles && shape.parts == 1;
}

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "single_layer.h"

#include "regular_triangulation.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <numeric>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

constexpr std::uint32_t NONE = ~std::uint32_t (0);

std::uint32_t
findRoot (std::vector<std::uint32_t>& parent, std::uint32_t a)
{
  while (parent[a] != a)
    a = parent[a] = parent[parent[a]];
  return a;
}

/** The Delaunay triangles around one vertex u, as the edges of its link: (a, b, triangle id) for
  * each triangle (u, a, b), sorted. */
std::vector<std::array<std::uint32_t, 3>>
linkOf (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours, std::uint32_t u,
        std::uint32_t first_tetrahedron)
{
  std::vector<std::uint32_t> star{first_tetrahedron};
  std::vector<std::array<std::uint32_t, 3>> link;
  for (std::size_t k = 0; k < star.size (); ++k)
  {
    const std::uint32_t t = star[k];
    const std::uint32_t* v = complex.vertices (3, t);
    for (int i = 0; i < 4; ++i)
    {
      if (v[i] == u)
        continue;
      // The facet opposite v[i] holds u: a link edge, and the way to the next tetrahedron of the star.
      std::array<std::uint32_t, 2> ab{};
      int m = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i && v[j] != u)
          ab[m++] = v[j];
      link.push_back ({std::min (ab[0], ab[1]), std::max (ab[0], ab[1]), complex.facet (3, t, i).id});
      const std::uint32_t next = neighbours[4 * std::size_t (t) + i];
      if (next != NO_NEIGHBOUR && std::find (star.begin (), star.end (), next) == star.end ())
        star.push_back (next);
    }
  }
  std::sort (link.begin (), link.end ());
  link.erase (std::unique (link.begin (), link.end ()), link.end ());
  return link;
}

/** The triangles of the fewest link edges of u from a vertex of \a from to one of \a to (both
  * sorted), by breadth-first search in the order of vertex ids; empty if none. */
std::vector<SimplexId>
linkPath (const std::vector<std::array<std::uint32_t, 3>>& link, const std::vector<std::uint32_t>& from,
          const std::vector<std::uint32_t>& to)
{
  std::vector<std::uint32_t> nodes;
  for (const auto& e : link)
    nodes.insert (nodes.end (), {e[0], e[1]});
  std::sort (nodes.begin (), nodes.end ());
  nodes.erase (std::unique (nodes.begin (), nodes.end ()), nodes.end ());
  const auto index = [&] (std::uint32_t a) {
    return static_cast<std::uint32_t> (std::lower_bound (nodes.begin (), nodes.end (), a) - nodes.begin ());
  };
  std::vector<std::vector<std::pair<std::uint32_t, SimplexId>>> next (nodes.size ());
  for (const auto& e : link)
  {
    next[index (e[0])].emplace_back (index (e[1]), e[2]);
    next[index (e[1])].emplace_back (index (e[0]), e[2]);
  }
  std::vector<std::uint32_t> came_from (nodes.size (), NONE), queue;
  std::vector<SimplexId> via (nodes.size (), NO_SIMPLEX);
  for (std::uint32_t a : from)
    if (std::binary_search (nodes.begin (), nodes.end (), a))
    {
      came_from[index (a)] = index (a);
      queue.push_back (index (a));
    }
  for (std::size_t k = 0; k < queue.size (); ++k)
  {
    const std::uint32_t a = queue[k];
    if (std::binary_search (to.begin (), to.end (), nodes[a]))
    {
      std::vector<SimplexId> path;
      for (std::uint32_t b = a; came_from[b] != b; b = came_from[b])
        path.push_back (via[b]);
      return path;
    }
    for (const auto& [b, triangle] : next[a])
      if (came_from[b] == NONE)
      {
        came_from[b] = a;
        via[b] = triangle;
        queue.push_back (b);
      }
  }
  return {};
}

/** The pieces of \a split (connected through edges) that meet another piece only at a vertex,
  * and the Delaunay triangles that tie them together: one path per pair of pieces to join, found
  * at their lowest shared vertex. */
std::vector<SimplexId>
bridges (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours,
         const ManifoldSplit& split, std::vector<std::uint32_t>& tet_of_vertex)
{
  const std::uint32_t nv = complex.numVertices ();
  const auto base = [&] (std::uint32_t v) { return v < nv ? v : split.copy_of[v - nv]; };
  std::vector<std::uint32_t> piece (nv + split.copy_of.size ());
  std::iota (piece.begin (), piece.end (), 0u);
  for (const auto& t : split.triangles)
  {
    piece[findRoot (piece, t[1])] = findRoot (piece, t[0]);
    piece[findRoot (piece, t[2])] = findRoot (piece, t[0]);
  }
  // (original vertex, piece, copy) for every corner, to find the vertices shared by pieces.
  std::vector<std::array<std::uint32_t, 3>> corners;
  for (const auto& t : split.triangles)
    for (std::uint32_t v : t)
      corners.push_back ({base (v), findRoot (piece, v), v});
  std::sort (corners.begin (), corners.end ());
  corners.erase (std::unique (corners.begin (), corners.end ()), corners.end ());

  std::vector<std::uint32_t> joined (piece.size ());
  std::iota (joined.begin (), joined.end (), 0u);
  std::vector<std::uint8_t> at_bridge (nv, 0);
  std::vector<std::array<std::uint32_t, 3>> pairs; // (vertex, piece a, piece b) to join
  for (std::size_t a = 0; a < corners.size ();)
  {
    std::size_t b = a;
    while (b < corners.size () && corners[b][0] == corners[a][0])
      ++b;
    for (std::size_t k = a + 1; k < b; ++k)
    {
      const std::uint32_t p = findRoot (joined, corners[a][1]), q = findRoot (joined, corners[k][1]);
      if (p == q)
        continue;
      joined[q] = p;
      pairs.push_back ({corners[a][0], corners[a][1], corners[k][1]});
      at_bridge[corners[a][0]] = 1;
    }
    a = b;
  }
  if (pairs.empty ())
    return {};

  // Per piece and shared vertex, the original vertices next to it: where a path may start or end.
  std::vector<std::array<std::uint32_t, 3>> sides; // (vertex, piece, neighbour)
  for (const auto& t : split.triangles)
    for (int i = 0; i < 3; ++i)
      if (at_bridge[base (t[i])])
        for (int j = 1; j < 3; ++j)
          sides.push_back ({base (t[i]), findRoot (piece, t[i]), base (t[(i + j) % 3])});
  std::sort (sides.begin (), sides.end ());
  const auto neighboursIn = [&] (std::uint32_t u, std::uint32_t p) {
    std::vector<std::uint32_t> out;
    auto at = std::lower_bound (sides.begin (), sides.end (), std::array<std::uint32_t, 3>{u, p, 0});
    for (; at != sides.end () && (*at)[0] == u && (*at)[1] == p; ++at)
      out.push_back ((*at)[2]);
    out.erase (std::unique (out.begin (), out.end ()), out.end ());
    return out;
  };

  if (tet_of_vertex.empty ())
  {
    tet_of_vertex.assign (nv, NONE);
    for (std::uint32_t t = 0; t < complex.size (3); ++t)
      for (int i = 0; i < 4; ++i)
        tet_of_vertex[complex.vertex (3, t, i)] = t;
  }
  std::vector<SimplexId> added;
  for (const auto& [u, p, q] : pairs)
  {
    if (tet_of_vertex[u] == NONE)
      continue;
    // Pieces that share an edge at u as well were split there: a path must leave that edge.
    const std::vector<std::uint32_t> from = neighboursIn (u, p), to_any = neighboursIn (u, q);
    std::vector<std::uint32_t> to;
    std::set_difference (to_any.begin (), to_any.end (), from.begin (), from.end (), std::back_inserter (to));
    const auto path = linkPath (linkOf (complex, neighbours, u, tet_of_vertex[u]), from, to);
    added.insert (added.end (), path.begin (), path.end ());
  }
  return added;
}

} // namespace

bool
isSingleLayer (const SimplicialComplex& complex, const Subcomplex& x, const std::vector<std::uint8_t>& inside)
{
  std::size_t solid = 0, in_x = 0;
  for (SimplexId t = 0; t < inside.size (); ++t)
    if (inside[t])
    {
      ++solid;
      in_x += x.contains ({3, t});
    }
  return complex.dimension () == 3 && 2 * in_x < solid;
}

std::size_t
verticesOn (const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  std::vector<std::uint32_t> v;
  v.reserve (3 * triangles.size ());
  for (const auto& t : triangles)
    v.insert (v.end (), t.begin (), t.end ());
  std::sort (v.begin (), v.end ());
  return static_cast<std::size_t> (std::unique (v.begin (), v.end ()) - v.begin ());
}

TwoSidedShell
twoSidedShell (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours, const Subcomplex& x)
{
  std::array<std::vector<std::uint8_t>, 4> members;
  for (int k = 0; k <= 3; ++k)
  {
    members[k].resize (complex.size (k));
    for (SimplexId s = 0; s < members[k].size (); ++s)
      members[k][s] = x.contains ({k, s});
  }
  TwoSidedShell shell;
  std::vector<std::uint32_t> tet_of_vertex;
  while (true)
  {
    const Subcomplex k (complex, members);
    shell.w = extractBoundary (complex, k);
    shell.split = splitPinches (complex, k, shell.w);
    std::vector<SimplexId> added = bridges (complex, neighbours, shell.split, tet_of_vertex);
    // Each round joins pieces or adds nothing new; a round that adds nothing ends it.
    added.erase (std::remove_if (added.begin (), added.end (), [&] (SimplexId f) { return members[2][f] != 0; }),
                 added.end ());
    if (added.empty ())
      return shell;
    for (SimplexId f : added)
      for (unsigned mask = 1; mask < 8; ++mask)
      {
        const Simplex g = complex.face (2, f, mask);
        members[g.dim][g.id] = 1;
      }
    shell.bridges += added.size ();
  }
}

} // namespace pcl_wrap::detail

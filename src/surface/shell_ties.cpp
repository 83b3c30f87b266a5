// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/shell_ties.h"

#include "surface/shell_pieces.h"
#include "util/distance.h"
#include "util/union_find.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <numeric>
#include <tuple>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

constexpr std::uint32_t NONE = ~std::uint32_t (0);

/** A corner of the shell: the original vertex, the piece of the shell, the vertex (or copy) there. */
struct Corner
{
  std::uint32_t vertex, piece, copy;
  bool operator<(const Corner& o) const
  {
    return std::tie (vertex, piece, copy) < std::tie (o.vertex, o.piece, o.copy);
  }
  bool operator== (const Corner& o) const { return vertex == o.vertex && piece == o.piece && copy == o.copy; }
};

/** Two pieces of the shell to tie at a vertex they share. */
struct PiecesToTie
{
  std::uint32_t vertex, piece, other;
};

/** A triangle (u, x, y) of one piece of the shell at its vertex u, with x < y. */
struct TriangleAt
{
  std::uint32_t u, piece, x, y;
  bool operator< (const TriangleAt& o) const { return std::tie (u, piece, x, y) < std::tie (o.u, o.piece, o.x, o.y); }
};

/** The squared length of the longest edge of \a s. */
double
longestEdge (const SimplicialComplex& complex, const std::vector<Point3>& positions, Simplex s)
{
  double longest = 0.0;
  const std::uint32_t* v = complex.vertices (s.dim, s.id);
  for (int i = 0; i <= s.dim; ++i)
    for (int j = 0; j < i; ++j)
      longest = std::max (longest, squaredDistance (positions[v[i]], positions[v[j]]));
  return longest;
}


/** An edge (x, y) of a link, and the simplex that gives it. */
struct LinkEdge
{
  std::uint32_t x, y;
  Simplex simplex;
  double size; ///< the simplex's longest edge, squared
  bool operator== (const LinkEdge& o) const { return x == o.x && y == o.y && simplex == o.simplex; }
};

/** The link of u: an edge (a, b) for each triangle (u, a, b) of its star. With \a w, the link of
  * the edge (u, w) instead: an edge (a, b) for each tetrahedron (u, w, a, b). */
std::vector<LinkEdge>
linkOf (const SimplicialComplex& complex, const std::vector<Point3>& positions, const Star& star, std::uint32_t u,
        std::uint32_t w = NONE)
{
  std::vector<LinkEdge> link;
  for (std::uint32_t t : star.tetrahedra ())
  {
    const std::uint32_t* v = complex.vertices (3, t);
    for (int i = 0; i < 4; ++i)
    {
      if (v[i] == u || (w != NONE && v[i] != w))
        continue;
      std::array<std::uint32_t, 2> ab{};
      int m = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i && v[j] != u)
          ab[m++] = v[j];
      const Simplex simplex = w == NONE ? complex.facet (3, t, i) : Simplex{3, t};
      link.push_back (
          {std::min (ab[0], ab[1]), std::max (ab[0], ab[1]), simplex, longestEdge (complex, positions, simplex)});
    }
  }
  std::sort (link.begin (), link.end (), [] (const LinkEdge& e, const LinkEdge& f) {
    return std::tie (e.x, e.y, e.simplex.id) < std::tie (f.x, f.y, f.simplex.id);
  });
  link.erase (std::unique (link.begin (), link.end ()), link.end ());
  return link;
}

/** A path of link edges from a vertex of \a from to one of \a to (both sorted) whose largest
  * simplex is as small as can be; with that, the fewest edges, found breadth-first in the order of
  * vertex ids. Empty if there is none. */
std::vector<Simplex>
linkPath (const std::vector<LinkEdge>& link, const std::vector<std::uint32_t>& from,
          const std::vector<std::uint32_t>& to)
{
  std::vector<std::uint32_t> nodes;
  for (const auto& e : link)
    nodes.insert (nodes.end (), {e.x, e.y});
  std::sort (nodes.begin (), nodes.end ());
  nodes.erase (std::unique (nodes.begin (), nodes.end ()), nodes.end ());
  const auto index = [&] (std::uint32_t a) {
    return static_cast<std::uint32_t> (std::lower_bound (nodes.begin (), nodes.end (), a) - nodes.begin ());
  };
  const auto in = [] (const std::vector<std::uint32_t>& set, std::uint32_t a) {
    return std::binary_search (set.begin (), set.end (), a);
  };
  // The bottleneck: add the link's edges smallest first until a part holds both ends.
  UnionFind part (nodes.size ());
  std::vector<std::uint8_t> ends (nodes.size (), 0); // per part: 1 holds a start, 2 a goal
  for (std::uint32_t a = 0; a < nodes.size (); ++a)
    ends[a] = (in (from, nodes[a]) ? 1 : 0) | (in (to, nodes[a]) ? 2 : 0);
  std::vector<std::size_t> order (link.size ());
  std::iota (order.begin (), order.end (), std::size_t (0));
  std::stable_sort (order.begin (), order.end (),
                    [&] (std::size_t i, std::size_t j) { return link[i].size < link[j].size; });
  double bottleneck = -1.0;
  for (std::size_t i : order)
  {
    const std::uint32_t a = part.find (index (link[i].x)), b = part.find (index (link[i].y));
    part.attach (b, a);
    ends[a] |= ends[b];
    if (ends[a] == 3)
    {
      bottleneck = link[i].size;
      break;
    }
  }
  if (bottleneck < 0.0)
    return {};
  std::vector<std::vector<std::pair<std::uint32_t, Simplex>>> next (nodes.size ());
  for (const auto& e : link)
    if (e.size <= bottleneck)
    {
      next[index (e.x)].emplace_back (index (e.y), e.simplex);
      next[index (e.y)].emplace_back (index (e.x), e.simplex);
    }
  std::vector<std::uint32_t> came_from (nodes.size (), NONE), queue;
  std::vector<Simplex> via (nodes.size ());
  for (std::uint32_t a = 0; a < nodes.size (); ++a)
    if (in (from, nodes[a]))
    {
      came_from[a] = a;
      queue.push_back (a);
    }
  for (std::size_t k = 0; k < queue.size (); ++k)
  {
    const std::uint32_t a = queue[k];
    if (in (to, nodes[a]))
    {
      std::vector<Simplex> path;
      for (std::uint32_t b = a; came_from[b] != b; b = came_from[b])
        path.push_back (via[b]);
      return path;
    }
    for (const auto& [b, simplex] : next[a])
      if (came_from[b] == NONE)
      {
        came_from[b] = a;
        via[b] = simplex;
        queue.push_back (b);
      }
  }
  return {};
}

/** Does simplex \a g of a tie meet the shell along an edge other than those of the triangles it
  * joins (\a mine, \a theirs)? The tie would close a loop through the shell there: a handle. */
bool
meetsElsewhere (const SimplicialComplex& complex, Simplex g, const std::vector<std::uint8_t>& edge_in_k,
                const std::vector<TriangleAt>& mine, const std::vector<TriangleAt>& theirs)
{
  const auto joined = [&] (std::uint32_t x, std::uint32_t y) {
    for (const auto* triangles : {&mine, &theirs})
      for (const auto& t : *triangles)
      {
        const auto has = [&] (std::uint32_t v) { return v == t.u || v == t.x || v == t.y; };
        if (has (x) && has (y))
          return true;
      }
    return false;
  };
  for (int i = 0; i <= g.dim; ++i)
    for (int j = 0; j < i; ++j)
    {
      const Simplex e = complex.face (g.dim, g.id, (1u << i) | (1u << j));
      if (edge_in_k[e.id] && !joined (complex.vertex (1, e.id, 0), complex.vertex (1, e.id, 1)))
        return true;
    }
  return false;
}

/** The squared length of the longest edge of the triangles. */
double
longestSide (const std::vector<Point3>& positions, const std::vector<TriangleAt>& triangles)
{
  double longest = 0.0;
  for (const auto& t : triangles)
    for (const auto& [a, b] : {std::pair{t.u, t.x}, std::pair{t.u, t.y}, std::pair{t.x, t.y}})
      longest = std::max (longest, squaredDistance (positions[a], positions[b]));
  return longest;
}


} // namespace

std::vector<Simplex>
shellTies (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions,
           const std::vector<std::uint8_t>& edge_in_k, const ManifoldSplit& split)
{
  const SimplicialComplex& complex = tetrahedra.complex ();
  const std::uint32_t nv = complex.numVertices ();
  UnionFind piece = piecesOf (split, nv);
  // Every corner, to find the vertices shared by pieces.
  std::vector<Corner> corners;
  for (const auto& t : split.triangles)
    for (std::uint32_t v : t)
      corners.push_back ({split.original (v, nv), piece.find (v), v});
  std::sort (corners.begin (), corners.end ());
  corners.erase (std::unique (corners.begin (), corners.end ()), corners.end ());

  UnionFind joined (piece.size ());
  std::vector<std::uint8_t> at_tie (nv, 0);
  std::vector<PiecesToTie> pairs;
  for (std::size_t a = 0; a < corners.size ();)
  {
    std::size_t b = a;
    while (b < corners.size () && corners[b].vertex == corners[a].vertex)
      ++b;
    for (std::size_t k = a + 1; k < b; ++k)
    {
      const std::uint32_t p = joined.find (corners[a].piece), q = joined.find (corners[k].piece);
      if (p == q)
        continue;
      joined.attach (q, p);
      pairs.push_back ({corners[a].vertex, corners[a].piece, corners[k].piece});
      at_tie[corners[a].vertex] = 1;
    }
    a = b;
  }
  if (pairs.empty ())
    return {};

  // Per shared vertex u and piece, the piece's triangles (u, x, y) at u.
  std::vector<TriangleAt> sides;
  for (const auto& t : split.triangles)
    for (int i = 0; i < 3; ++i)
      if (at_tie[split.original (t[i], nv)])
      {
        const std::uint32_t x = split.original (t[(i + 1) % 3], nv), y = split.original (t[(i + 2) % 3], nv);
        sides.push_back ({split.original (t[i], nv), piece.find (t[i]), std::min (x, y), std::max (x, y)});
      }
  std::sort (sides.begin (), sides.end ());
  const auto trianglesAt = [&] (std::uint32_t u, std::uint32_t p) {
    const auto first = std::lower_bound (sides.begin (), sides.end (), TriangleAt{u, p, 0, 0});
    auto last = first;
    while (last != sides.end () && last->u == u && last->piece == p)
      ++last;
    return std::vector<TriangleAt> (first, last);
  };
  // The third vertices of the triangles (u, a, c) of a piece, sorted; with a = NONE, all their vertices.
  const auto around = [] (const std::vector<TriangleAt>& triangles, std::uint32_t a) {
    std::vector<std::uint32_t> out;
    for (const auto& t : triangles)
      if (a == NONE)
        out.insert (out.end (), {t.x, t.y});
      else if (t.x == a || t.y == a)
        out.push_back (t.x == a ? t.y : t.x);
    std::sort (out.begin (), out.end ());
    out.erase (std::unique (out.begin (), out.end ()), out.end ());
    return out;
  };

  std::vector<Simplex> added;
  Star star;
  for (const auto& [u, p, q] : pairs)
  {
    if (tetrahedra.tetrahedronOf (u) == NO_TETRAHEDRON)
      continue;
    const auto mine = trianglesAt (u, p), theirs = trianglesAt (u, q);
    const std::vector<std::uint32_t> from = around (mine, NONE), to = around (theirs, NONE);
    std::vector<std::uint32_t> shared;
    std::set_intersection (from.begin (), from.end (), to.begin (), to.end (), std::back_inserter (shared));
    tetrahedra.gatherStar (u, star);
    // Pieces that share an edge (u, a) were split apart there: as one sheet, both its sides would
    // close up at u and a. The tetrahedra around the edge from one piece's triangle to the
    // other's make them one solid wedge there; pieces that share only u get a fan of triangles.
    // Either way round, a path only through simplices that meet no other edge of the shell and
    // are no longer than the triangles joined: a longer one would lie across the layer.
    std::vector<LinkEdge> link = shared.empty () ? linkOf (complex, positions, star, u)
                                                 : linkOf (complex, positions, star, u, shared.front ());
    const double longest = std::max (longestSide (positions, mine), longestSide (positions, theirs));
    link.erase (std::remove_if (link.begin (), link.end (),
                                [&] (const LinkEdge& e) {
                                  return e.size > longest ||
                                         meetsElsewhere (complex, e.simplex, edge_in_k, mine, theirs);
                                }),
                link.end ());
    const std::vector<Simplex> path =
        shared.empty () ? linkPath (link, from, to)
                        : linkPath (link, around (mine, shared.front ()), around (theirs, shared.front ()));
    added.insert (added.end (), path.begin (), path.end ());
  }
  return added;
}


} // namespace pcl_wrap::detail

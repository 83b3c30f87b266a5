// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/single_layer.h"

#include "delaunay/regular_triangulation.h"

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

std::uint32_t
findRoot (std::vector<std::uint32_t>& parent, std::uint32_t a)
{
  while (parent[a] != a)
    a = parent[a] = parent[parent[a]];
  return a;
}

double
squaredDistance (const Point3& p, const Point3& q)
{
  return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
}

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

/** The Delaunay tetrahedra around vertex u (its star), from one of them. */
std::vector<std::uint32_t>
starOf (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours, std::uint32_t u,
        std::uint32_t first_tetrahedron)
{
  std::vector<std::uint32_t> star{first_tetrahedron};
  for (std::size_t k = 0; k < star.size (); ++k)
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t t = star[k], next = neighbours[4 * std::size_t (t) + i];
      if (complex.vertex (3, t, i) != u && next != NO_NEIGHBOUR && std::find (star.begin (), star.end (), next) == star.end ())
        star.push_back (next); // across a facet that holds u
    }
  return star;
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
linkOf (const SimplicialComplex& complex, const std::vector<Point3>& positions, const std::vector<std::uint32_t>& star,
        std::uint32_t u, std::uint32_t w = NONE)
{
  std::vector<LinkEdge> link;
  for (std::uint32_t t : star)
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
      link.push_back ({std::min (ab[0], ab[1]), std::max (ab[0], ab[1]), simplex, longestEdge (complex, positions, simplex)});
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
linkPath (const std::vector<LinkEdge>& link, const std::vector<std::uint32_t>& from, const std::vector<std::uint32_t>& to)
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
  std::vector<std::uint32_t> part (nodes.size ());
  std::iota (part.begin (), part.end (), 0u);
  std::vector<std::uint8_t> ends (nodes.size (), 0); // per part: 1 holds a start, 2 a goal
  for (std::uint32_t a = 0; a < nodes.size (); ++a)
    ends[a] = (in (from, nodes[a]) ? 1 : 0) | (in (to, nodes[a]) ? 2 : 0);
  std::vector<std::size_t> order (link.size ());
  std::iota (order.begin (), order.end (), std::size_t (0));
  std::stable_sort (order.begin (), order.end (), [&] (std::size_t i, std::size_t j) { return link[i].size < link[j].size; });
  double bottleneck = -1.0;
  for (std::size_t i : order)
  {
    const std::uint32_t a = findRoot (part, index (link[i].x)), b = findRoot (part, index (link[i].y));
    part[b] = a;
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

/** Does simplex \a g of a bridge meet the shell along an edge other than those of the triangles
  * it joins (\a mine, \a theirs: (u, piece, x, y) for the triangles (u, x, y))? The bridge would
  * close a loop through the shell there: a handle. */
bool
meetsElsewhere (const SimplicialComplex& complex, Simplex g, const std::vector<std::uint8_t>& edge_in_k,
                const std::vector<std::array<std::uint32_t, 4>>& mine,
                const std::vector<std::array<std::uint32_t, 4>>& theirs)
{
  const auto joined = [&] (std::uint32_t x, std::uint32_t y) {
    for (const auto* triangles : {&mine, &theirs})
      for (const auto& t : *triangles)
      {
        const auto has = [&] (std::uint32_t v) { return v == t[0] || v == t[2] || v == t[3]; };
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

/** The squared length of the longest edge of the triangles (u, piece, x, y) = (u, x, y). */
double
longestSide (const std::vector<Point3>& positions, const std::vector<std::array<std::uint32_t, 4>>& triangles)
{
  double longest = 0.0;
  for (const auto& t : triangles)
    for (const auto& [i, j] : {std::pair{0, 2}, std::pair{0, 3}, std::pair{2, 3}})
      longest = std::max (longest, squaredDistance (positions[t[i]], positions[t[j]]));
  return longest;
}

/** Per vertex id of \a split (copies included), a union-find parent: vertices of one piece
  * (connected through triangles) share a root. */
std::vector<std::uint32_t>
piecesOf (const ManifoldSplit& split, std::uint32_t nv)
{
  std::vector<std::uint32_t> piece (nv + split.copy_of.size ());
  std::iota (piece.begin (), piece.end (), 0u);
  for (const auto& t : split.triangles)
  {
    piece[findRoot (piece, t[1])] = findRoot (piece, t[0]);
    piece[findRoot (piece, t[2])] = findRoot (piece, t[0]);
  }
  return piece;
}

/** The pieces of a closed surface and its Euler characteristic. */
struct Topology
{
  std::size_t pieces = 0;
  long euler = 0;
  long genus () const { return (2 * long (pieces) - euler) / 2; }
};

Topology
topologyOf (const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  std::vector<std::uint32_t> vertices;
  for (const auto& t : triangles)
    vertices.insert (vertices.end (), t.begin (), t.end ());
  std::sort (vertices.begin (), vertices.end ());
  vertices.erase (std::unique (vertices.begin (), vertices.end ()), vertices.end ());
  const auto index = [&] (std::uint32_t v) {
    return static_cast<std::uint32_t> (std::lower_bound (vertices.begin (), vertices.end (), v) - vertices.begin ());
  };
  std::vector<std::uint32_t> piece (vertices.size ());
  std::iota (piece.begin (), piece.end (), 0u);
  for (const auto& t : triangles)
  {
    piece[findRoot (piece, index (t[1]))] = findRoot (piece, index (t[0]));
    piece[findRoot (piece, index (t[2]))] = findRoot (piece, index (t[0]));
  }
  Topology out;
  for (std::uint32_t v = 0; v < piece.size (); ++v)
    out.pieces += piece[v] == v;
  // Closed: every edge in two triangles, E = 3F / 2.
  out.euler = long (vertices.size ()) - long (3 * triangles.size () / 2) + long (triangles.size ());
  return out;
}

/** The simplices that tie together the pieces of \a split (connected through edges) that share
  * a vertex: for each pair of pieces to join, at their lowest shared vertex u, the tetrahedra
  * around an edge they share or the triangles around u from one to the other, through none that
  * would make a handle (meetsElsewhere) or is longer than the triangles joined. \a edge_in_k:
  * per edge, in the complex split. */
std::vector<Simplex>
bridges (const SimplicialComplex& complex, const std::vector<Point3>& positions,
         const FilledInParallel<std::uint32_t>& neighbours, const std::vector<std::uint8_t>& edge_in_k,
         const ManifoldSplit& split, std::vector<std::uint32_t>& tet_of_vertex)
{
  const std::uint32_t nv = complex.numVertices ();
  const auto base = [&] (std::uint32_t v) { return v < nv ? v : split.copy_of[v - nv]; };
  std::vector<std::uint32_t> piece = piecesOf (split, nv);
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

  // Per shared vertex u and piece, the piece's triangles (u, x, y) at u, as (u, piece, x, y).
  std::vector<std::array<std::uint32_t, 4>> sides;
  for (const auto& t : split.triangles)
    for (int i = 0; i < 3; ++i)
      if (at_bridge[base (t[i])])
      {
        const std::uint32_t x = base (t[(i + 1) % 3]), y = base (t[(i + 2) % 3]);
        sides.push_back ({base (t[i]), findRoot (piece, t[i]), std::min (x, y), std::max (x, y)});
      }
  std::sort (sides.begin (), sides.end ());
  const auto trianglesAt = [&] (std::uint32_t u, std::uint32_t p) {
    const auto first = std::lower_bound (sides.begin (), sides.end (), std::array<std::uint32_t, 4>{u, p, 0, 0});
    auto last = first;
    while (last != sides.end () && (*last)[0] == u && (*last)[1] == p)
      ++last;
    return std::vector<std::array<std::uint32_t, 4>> (first, last);
  };
  // The third vertices of the triangles (u, a, c) of a piece, sorted; with a = NONE, all their vertices.
  const auto around = [] (const std::vector<std::array<std::uint32_t, 4>>& triangles, std::uint32_t a) {
    std::vector<std::uint32_t> out;
    for (const auto& t : triangles)
      if (a == NONE)
        out.insert (out.end (), {t[2], t[3]});
      else if (t[2] == a || t[3] == a)
        out.push_back (t[2] == a ? t[3] : t[2]);
    std::sort (out.begin (), out.end ());
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
  std::vector<Simplex> added;
  for (const auto& [u, p, q] : pairs)
  {
    if (tet_of_vertex[u] == NONE)
      continue;
    const auto mine = trianglesAt (u, p), theirs = trianglesAt (u, q);
    const std::vector<std::uint32_t> from = around (mine, NONE), to = around (theirs, NONE);
    std::vector<std::uint32_t> shared;
    std::set_intersection (from.begin (), from.end (), to.begin (), to.end (), std::back_inserter (shared));
    const std::vector<std::uint32_t> star = starOf (complex, neighbours, u, tet_of_vertex[u]);
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
                                  return e.size > longest || meetsElsewhere (complex, e.simplex, edge_in_k, mine, theirs);
                                }),
                link.end ());
    const std::vector<Simplex> path =
        shared.empty () ? linkPath (link, from, to)
                        : linkPath (link, around (mine, shared.front ()), around (theirs, shared.front ()));
    added.insert (added.end (), path.begin (), path.end ());
  }
  return added;
}

} // namespace

/** Joins pieces that the split left apart along an edge. Where k >= 2 pieces meet only along the
  * points a, b of an edge, two triangles each (triangles hanging from the rim of a scan, each
  * closed as a piece of its own), the pieces are taken in a cycle: piece i's triangle (a, b, u)
  * and the next piece's (b, a, w) make a quadrilateral, which takes the other diagonal: (a, w, u)
  * and (w, b, u). The pieces' copies of a and b become one and the edge (a, b) leaves the
  * surface; every edge stays in two triangles, once each way, and k spheres make one. Returns
  * how many pieces it joined to others. */
std::size_t
joinAlongSharedEdges (ManifoldSplit& split, std::uint32_t nv)
{
  auto& triangles = split.triangles;
  const auto base = [&] (std::uint32_t v) { return v < nv ? v : split.copy_of[v - nv]; };
  std::vector<std::uint32_t> piece = piecesOf (split, nv);
  // Every triangle side, by the undirected edge of the points it joins.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> by_edge;
  by_edge.reserve (3 * triangles.size ());
  for (std::uint32_t i = 0; i < triangles.size (); ++i)
    for (int k = 0; k < 3; ++k)
      by_edge.emplace_back (edgeKey (base (triangles[i][k]), base (triangles[i][(k + 1) % 3])), i);
  std::sort (by_edge.begin (), by_edge.end ());

  std::vector<std::uint32_t> merged (piece.size ()), same (piece.size ()); // pieces joined; ids made one
  std::iota (merged.begin (), merged.end (), 0u);
  std::iota (same.begin (), same.end (), 0u);
  std::vector<std::uint8_t> gone (triangles.size (), 0), busy (piece.size (), 0);
  std::vector<std::array<std::uint32_t, 3>> added;
  std::size_t joins = 0;
  for (std::size_t e = 0; e < by_edge.size ();)
  {
    std::size_t f = e;
    while (f < by_edge.size () && by_edge[f].first == by_edge[e].first)
      ++f;
    const std::size_t first = std::exchange (e, f);
    if (f - first < 4 || (f - first) % 2 != 0)
      continue; // an edge of one piece, or of an odd number of triangles
    const std::uint32_t a = std::uint32_t (by_edge[first].first >> 32), b = std::uint32_t (by_edge[first].first);
    std::vector<std::uint32_t> on;
    for (std::size_t k = first; k < f; ++k)
      on.push_back (by_edge[k].second);
    if (std::any_of (on.begin (), on.end (), [&] (std::uint32_t i) { return gone[i]; }))
      continue;
    std::sort (on.begin (), on.end (), [&] (std::uint32_t i, std::uint32_t j) {
      return std::make_pair (findRoot (piece, triangles[i][0]), i) < std::make_pair (findRoot (piece, triangles[j][0]), j);
    });
    // Per piece: its triangle from a to b and its triangle back, as (a's id, b's id, third vertex).
    const std::size_t k = on.size () / 2;
    std::vector<std::uint32_t> owner (k);
    std::vector<std::array<std::uint32_t, 3>> forth (k), back (k);
    bool fits = true;
    for (std::size_t i = 0; i < k && fits; ++i)
    {
      owner[i] = findRoot (piece, triangles[on[2 * i]][0]);
      fits = findRoot (piece, triangles[on[2 * i + 1]][0]) == owner[i] && (i == 0 || owner[i] != owner[i - 1]);
      int ways = 0;
      for (std::size_t j = 2 * i; j < 2 * i + 2; ++j)
      {
        std::array<std::uint32_t, 3> t = triangles[on[j]];
        while (base (t[0]) != a)
          std::rotate (t.begin (), t.begin () + 1, t.end ());
        if (base (t[1]) == b)
        {
          forth[i] = t;
          ways |= 1;
        }
        else
        {
          back[i] = {t[0], t[2], t[1]};
          ways |= 2;
        }
      }
      // One triangle each way, through the same copies of a and b, none touched by a join yet.
      fits = fits && ways == 3 && forth[i][0] == back[i][0] && forth[i][1] == back[i][1];
      for (const auto* t : {&forth[i], &back[i]})
        for (std::uint32_t v : *t)
          fits = fits && !busy[v];
    }
    for (std::size_t i = 0; i < k && fits; ++i)
      for (std::size_t j = 0; j < i && fits; ++j)
        fits = findRoot (merged, owner[i]) != findRoot (merged, owner[j]);
    if (!fits)
      continue;
    // The new diagonals (u, w), piece i's third vertex and the next piece's, must differ.
    std::vector<std::uint64_t> diagonals (k);
    for (std::size_t i = 0; i < k; ++i)
      diagonals[i] = edgeKey (forth[i][2], back[(i + 1) % k][2]);
    std::sort (diagonals.begin (), diagonals.end ());
    if (std::adjacent_find (diagonals.begin (), diagonals.end ()) != diagonals.end ())
      continue;
    const std::uint32_t ia = forth[0][0], ib = forth[0][1];
    for (std::size_t i = 0; i < k; ++i)
    {
      const std::uint32_t u = forth[i][2], w = back[(i + 1) % k][2];
      added.push_back ({ia, w, u});
      added.push_back ({w, ib, u});
      same[forth[i][0]] = ia;
      same[forth[i][1]] = ib;
      merged[findRoot (merged, owner[i])] = findRoot (merged, owner[0]);
      for (const auto* t : {&forth[i], &back[i]})
        for (std::uint32_t v : *t)
          busy[v] = 1;
    }
    for (std::uint32_t i : on)
      gone[i] = 1;
    joins += k - 1;
  }
  if (joins == 0)
    return 0;
  std::size_t n = 0;
  for (std::uint32_t i = 0; i < triangles.size (); ++i)
    if (!gone[i])
      triangles[n++] = triangles[i];
  triangles.resize (n);
  triangles.insert (triangles.end (), added.begin (), added.end ());
  for (auto& t : triangles)
    for (std::uint32_t& v : t)
      v = findRoot (same, v);
  return joins;
}

namespace
{

/** Drops the copies of points that no triangle of \a split uses any more. */
void
dropUnusedCopies (ManifoldSplit& split, std::uint32_t nv)
{
  std::vector<std::uint32_t> renamed (split.copy_of.size (), NONE);
  for (const auto& t : split.triangles)
    for (std::uint32_t v : t)
      if (v >= nv)
        renamed[v - nv] = 0;
  std::uint32_t kept = 0;
  for (std::uint32_t c = 0; c < renamed.size (); ++c)
    if (renamed[c] != NONE)
    {
      split.copy_of[kept] = split.copy_of[c];
      renamed[c] = nv + kept++;
    }
  split.copy_of.resize (kept);
  for (auto& t : split.triangles)
    for (std::uint32_t& v : t)
      if (v >= nv)
        v = renamed[v - nv];
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
twoSidedShell (const SimplicialComplex& complex, const std::vector<Point3>& positions,
               const FilledInParallel<std::uint32_t>& neighbours, const Subcomplex& x)
{
  std::array<std::vector<std::uint8_t>, 4> members;
  for (int k = 0; k <= 3; ++k)
  {
    members[k].resize (complex.size (k));
    for (SimplexId s = 0; s < members[k].size (); ++s)
      members[k][s] = x.contains ({k, s});
  }
  const auto shellOf = [&] (const std::array<std::vector<std::uint8_t>, 4>& m) {
    const Subcomplex k (complex, m);
    TwoSidedShell out;
    out.w = extractBoundary (complex, k);
    out.split = splitPinches (complex, k, out.w);
    return out;
  };
  TwoSidedShell shell = shellOf (members);
  Topology now = topologyOf (shell.split.triangles);
  std::vector<std::uint32_t> tet_of_vertex;
  while (now.pieces > 1)
  {
    std::vector<Simplex> added = bridges (complex, positions, neighbours, members[1], shell.split, tet_of_vertex);
    added.erase (std::remove_if (added.begin (), added.end (), [&] (Simplex s) { return members[s.dim][s.id] != 0; }),
                 added.end ());
    if (added.empty ())
      break;
    std::array<std::vector<std::uint8_t>, 4> more = members;
    for (const Simplex s : added)
      for (unsigned mask = 1; mask < (1u << (s.dim + 1)); ++mask)
      {
        const Simplex g = complex.face (s.dim, s.id, mask);
        more[g.dim][g.id] = 1;
      }
    TwoSidedShell tied = shellOf (more);
    const Topology then = topologyOf (tied.split.triangles);
    // A round is kept when it leaves fewer pieces and no new handle; each kept round adds
    // simplices, so the rounds end.
    if (then.pieces >= now.pieces || then.genus () > now.genus ())
      break;
    tied.bridges = shell.bridges + added.size ();
    members = std::move (more);
    shell = std::move (tied);
    now = then;
  }
  // Each pass joins pairs of the pieces it starts from; a piece joined in one may meet the next
  // one only in the next.
  std::size_t joined = 0;
  if (now.pieces > 1)
    for (std::size_t j; (j = joinAlongSharedEdges (shell.split, complex.numVertices ())) > 0;)
      joined += j;
  if (joined > 0)
    dropUnusedCopies (shell.split, complex.numVertices ());
  return shell;
}

} // namespace pcl_wrap::detail

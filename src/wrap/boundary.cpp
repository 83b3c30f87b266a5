// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap/boundary.h"

#include "util/parallel_for_each.h"
#include "delaunay/regular_triangulation.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <functional>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

using Triangle = std::array<std::uint32_t, 3>;

bool
hasDirectedEdge (const Triangle& t, std::uint32_t u, std::uint32_t v)
{
  for (int i = 0; i < 3; ++i)
    if (t[i] == u && t[(i + 1) % 3] == v)
      return true;
  return false;
}

} // namespace

void
orientSheetTriangles (std::vector<Triangle>& triangles, const std::function<std::uint32_t (std::uint32_t)>& key)
{
  // Everything below is in keys, so that the result depends on the set of triangles and the keys
  // alone: not on the order of the list, nor on how the caller numbers vertices.
  const std::size_t n = triangles.size ();
  std::vector<Triangle> keyed (n);
  parallelForEach (n, [&] (std::size_t i) {
    for (int c = 0; c < 3; ++c)
      keyed[i][c] = key (triangles[i][c]);
  });
  std::vector<Triangle> ascending (n); // each triangle's keys, sorted once
  parallelForEach (n, [&] (std::size_t i) {
    ascending[i] = keyed[i];
    std::sort (ascending[i].begin (), ascending[i].end ());
  });
  std::vector<std::uint32_t> order (n);
  for (std::uint32_t i = 0; i < n; ++i)
    order[i] = i;
  tbb::parallel_sort (order.begin (), order.end (),
                      [&] (std::uint32_t a, std::uint32_t b) { return ascending[a] < ascending[b]; });
  // (edge as its two keys ascending, rank of the triangle in order)
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edge_uses (3 * n);
  parallelForEach (n, [&] (std::size_t r) {
    const Triangle& t = keyed[order[r]];
    for (int e = 0; e < 3; ++e)
    {
      const std::uint32_t u = std::min (t[e], t[(e + 1) % 3]), w = std::max (t[e], t[(e + 1) % 3]);
      edge_uses[3 * r + e] = {std::uint64_t (u) << 32 | w, static_cast<std::uint32_t> (r)};
    }
  });
  tbb::parallel_sort (edge_uses.begin (), edge_uses.end ());
  // At most one neighbour across each of a triangle's three edges: a flat array, not a list each.
  constexpr std::uint32_t NONE = ~std::uint32_t (0);
  std::vector<std::array<std::uint32_t, 3>> neighbours (n, {NONE, NONE, NONE});
  const auto link = [&] (std::uint32_t i, std::uint32_t j) {
    *std::find (neighbours[i].begin (), neighbours[i].end (), NONE) = j;
  };
  for (std::size_t a = 0; a < edge_uses.size ();)
  {
    std::size_t b = a;
    while (b < edge_uses.size () && edge_uses[b].first == edge_uses[a].first)
      ++b;
    if (b - a == 2)
    {
      link (edge_uses[a].second, edge_uses[a + 1].second);
      link (edge_uses[a + 1].second, edge_uses[a].second);
    }
    a = b;
  }
  // Each sheet starts from its first triangle in order, its keys ascending, and spreads from there.
  std::vector<std::uint8_t> done (n, 0);
  std::vector<std::uint32_t> stack;
  for (std::uint32_t root = 0; root < n; ++root)
  {
    if (done[root])
      continue;
    done[root] = 1;
    keyed[order[root]] = ascending[order[root]];
    stack.push_back (root);
    while (!stack.empty ())
    {
      const std::uint32_t i = stack.back ();
      stack.pop_back ();
      const Triangle& t = keyed[order[i]];
      for (std::uint32_t j : neighbours[i])
      {
        if (j == NONE || done[j])
          continue;
        done[j] = 1;
        Triangle& nb = keyed[order[j]];
        // The shared edge, traversed as in t; the neighbour must traverse it the other way.
        for (int e = 0; e < 3; ++e)
        {
          const std::uint32_t u = t[e], w = t[(e + 1) % 3];
          if (std::count (nb.begin (), nb.end (), u) && std::count (nb.begin (), nb.end (), w))
          {
            if (hasDirectedEdge (nb, u, w))
              std::swap (nb[1], nb[2]);
            break;
          }
        }
        stack.push_back (j);
      }
    }
  }
  // Back to the caller's vertices, each triangle turned as its keys are.
  parallelForEach (n, [&] (std::size_t i) {
    Triangle& t = triangles[i];
    if (!hasDirectedEdge (keyed[i], key (t[0]), key (t[1])))
      std::swap (t[1], t[2]);
  });
}

namespace
{

/** Appends to \a w the facets that \a facets_of (t) flags (bit i: the facet opposite local vertex
  * i) of every tetrahedron t, each oriented away from its tetrahedron, in the order of the
  * tetrahedra; on all threads. */
template <class FacetsOf>
void
writeFacets (const SimplicialComplex& complex, const FacetsOf& facets_of, Boundary& w)
{
  fillInOrder (
      complex.size (3), [&] (std::size_t t) { return std::size_t (maskSize (facets_of (t))); },
      [&] (std::size_t total) {
        w.triangles.resize (total);
        w.triangle_ids.resize (total);
      },
      [&] (std::size_t id, std::size_t at) {
        const auto t = static_cast<SimplexId> (id);
        const std::uint32_t* v = complex.vertices (3, t);
        const unsigned mask = facets_of (id);
        for (int i = 0; i < 4; ++i)
          if (mask & (1u << i))
          {
            const int* o = OUTWARD_FACET[i];
            w.triangles[at] = {v[o[0]], v[o[1]], v[o[2]]};
            w.triangle_ids[at++] = complex.facet (3, t, i).id;
          }
        return at;
      });
}

} // namespace

Boundary
extractBoundary (const SimplicialComplex& complex, const Subcomplex& x, bool orient_sheets,
                 const std::function<std::uint32_t (std::uint32_t)>& sheet_key)
{
  Boundary w;
  // Facets of X's tetrahedra with one tetrahedron of X, found once (a mask per tetrahedron).
  std::vector<std::uint8_t> facets (complex.size (3), 0);
  parallelForEach (complex.size (3), [&] (std::size_t id) {
    const auto t = static_cast<SimplexId> (id);
    if (x.contains ({3, t}))
      for (int i = 0; i < 4; ++i)
        if (x.cofaceCount (complex.facet (3, t, i)) == 1)
          facets[t] |= 1u << i;
  });
  writeFacets (complex, [&] (std::size_t t) { return unsigned (facets[t]); }, w);
  facets = {};

  // The simplices of X with no coface in X, per dimension.
  const auto principal = [&] (int k) {
    const auto is_principal = [&] (std::size_t s) {
      const Simplex simplex{k, static_cast<SimplexId> (s)};
      return x.contains (simplex) && x.cofaceCount (simplex) == 0;
    };
    std::vector<SimplexId> found;
    fillInOrder (
        complex.size (k), [&] (std::size_t s) { return std::size_t (is_principal (s)); },
        [&] (std::size_t total) { found.resize (total); },
        [&] (std::size_t s, std::size_t at) {
          if (is_principal (s))
            found[at++] = static_cast<SimplexId> (s);
          return at;
        });
    return found;
  };
  const std::vector<SimplexId> sheet = principal (2);
  std::vector<Triangle> sheet_triangles (sheet.size ());
  parallelForEach (sheet.size (), [&] (std::size_t i) {
    const std::uint32_t* v = complex.vertices (2, sheet[i]);
    sheet_triangles[i] = {v[0], v[1], v[2]};
  });
  if (orient_sheets)
    orientSheetTriangles (
        sheet_triangles, sheet_key ? sheet_key : [] (std::uint32_t v) { return v; });
  w.triangles.insert (w.triangles.end (), sheet_triangles.begin (), sheet_triangles.end ());
  w.triangle_ids.insert (w.triangle_ids.end (), sheet.begin (), sheet.end ());
  for (SimplexId e : principal (1))
  {
    const std::uint32_t* v = complex.vertices (1, e);
    w.dangling_edges.push_back ({v[0], v[1]});
  }
  w.isolated_vertices = principal (0);
  return w;
}

Boundary
extractSolidBoundary (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside)
{
  // The facets to write, found once (a mask per tetrahedron): writeFacets() asks twice.
  FilledInParallel<std::uint8_t> facets (inside.size ());
  parallelForEach (inside.size (), [&] (std::size_t t) {
    unsigned mask = 0;
    if (inside[t])
      for (int i = 0; i < 4; ++i)
      {
        const std::uint32_t u = tetrahedra.neighbour (static_cast<std::uint32_t> (t), i);
        if (u == OUTSIDE_HULL || !inside[u])
          mask |= 1u << i;
      }
    facets[t] = static_cast<std::uint8_t> (mask);
  });
  Boundary w;
  writeFacets (
      tetrahedra.complex (), [&] (std::size_t t) { return unsigned (facets[t]); }, w);
  return w;
}

} // namespace pcl_wrap::detail

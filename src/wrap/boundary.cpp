// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap/boundary.h"

#include "util/parallel_for_each.h"
#include "delaunay/regular_triangulation.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

// For a positively oriented tetrahedron, the facet opposite local vertex i listed so that its
// normal points away from vertex i: orientation(a, b, c, v_i) < 0 for (a, b, c) below.
constexpr int OUTWARD_FACET[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

using Triangle = std::array<std::uint32_t, 3>;

bool
hasDirectedEdge (const Triangle& t, std::uint32_t u, std::uint32_t v)
{
  for (int i = 0; i < 3; ++i)
    if (t[i] == u && t[(i + 1) % 3] == v)
      return true;
  return false;
}

/** Orients the sheet triangles (those with no tetrahedron behind them) so that neighbours across
  * an edge shared by exactly two of them traverse it in opposite directions. */
void
orientSheets (const SimplicialComplex& complex, const std::vector<SimplexId>& sheet, std::vector<Triangle>& out)
{
  const std::size_t first = out.size ();
  out.resize (first + sheet.size ());
  std::vector<std::pair<SimplexId, std::uint32_t>> edge_uses (3 * sheet.size ()); // (edge id, index in sheet)
  parallelForEach (sheet.size (), [&] (std::size_t i) {
    const std::uint32_t* v = complex.vertices (2, sheet[i]);
    out[first + i] = {v[0], v[1], v[2]};
    int k = 0;
    for (unsigned mask : {3u, 5u, 6u})
      edge_uses[3 * i + k++] = {complex.face (2, sheet[i], mask).id, static_cast<std::uint32_t> (i)};
  });
  tbb::parallel_sort (edge_uses.begin (), edge_uses.end ());
  // At most one neighbour across each of a triangle's three edges: a flat array, not a list each.
  constexpr std::uint32_t NONE = ~std::uint32_t (0);
  std::vector<std::array<std::uint32_t, 3>> neighbours (sheet.size (), {NONE, NONE, NONE});
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
  std::vector<std::uint8_t> done (sheet.size (), 0);
  std::vector<std::uint32_t> stack;
  for (std::uint32_t root = 0; root < sheet.size (); ++root)
  {
    if (done[root])
      continue;
    done[root] = 1;
    stack.push_back (root);
    while (!stack.empty ())
    {
      const std::uint32_t i = stack.back ();
      stack.pop_back ();
      const Triangle& t = out[first + i];
      for (std::uint32_t j : neighbours[i])
      {
        if (j == NONE || done[j])
          continue;
        done[j] = 1;
        Triangle& n = out[first + j];
        // The shared edge, traversed as in t; the neighbour must traverse it the other way.
        for (int e = 0; e < 3; ++e)
        {
          const std::uint32_t u = t[e], w = t[(e + 1) % 3];
          if (std::count (n.begin (), n.end (), u) && std::count (n.begin (), n.end (), w))
          {
            if (hasDirectedEdge (n, u, w))
              std::swap (n[1], n[2]);
            break;
          }
        }
        stack.push_back (j);
      }
    }
  }
}

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
extractBoundary (const SimplicialComplex& complex, const Subcomplex& x, bool orient_sheets)
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
  if (orient_sheets)
    orientSheets (complex, sheet, w.triangles);
  else
    for (SimplexId id : sheet)
    {
      const std::uint32_t* v = complex.vertices (2, id);
      w.triangles.push_back ({v[0], v[1], v[2]});
    }
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
  Boundary w;
  writeFacets (
      tetrahedra.complex (),
      [&] (std::size_t t) {
        unsigned mask = 0;
        if (inside[t])
          for (int i = 0; i < 4; ++i)
          {
            const std::uint32_t u = tetrahedra.neighbour (static_cast<std::uint32_t> (t), i);
            if (u == OUTSIDE_HULL || !inside[u])
              mask |= 1u << i;
          }
        return mask;
      },
      w);
  return w;
}

} // namespace pcl_wrap::detail

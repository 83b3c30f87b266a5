// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "topology.h"

#include <algorithm>
#include <numeric>
#include <set>

namespace pcl_wrap::test
{
namespace
{

struct UnionFind
{
  std::map<std::uint32_t, std::uint32_t> parent;
  std::uint32_t find (std::uint32_t a)
  {
    if (!parent.count (a))
      parent[a] = a;
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  }
  void join (std::uint32_t a, std::uint32_t b) { parent[find (a)] = find (b); }
  std::size_t roots ()
  {
    std::size_t n = 0;
    for (auto& [a, p] : parent)
      n += find (a) == a;
    return n;
  }
};

/** Rank over GF(2) of the boundary matrix from triangles to edges, by column reduction. */
std::size_t
rankOfTriangleBoundary (const std::vector<Tuple>& complex)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_row;
  for (const auto& s : complex)
    if (s.size () == 2)
      edge_row.emplace (std::make_pair (s[0], s[1]), static_cast<std::uint32_t> (edge_row.size ()));
  std::map<std::uint32_t, std::vector<std::uint32_t>> column_of_pivot;
  std::size_t rank = 0;
  for (const auto& s : complex)
  {
    if (s.size () != 3)
      continue;
    std::vector<std::uint32_t> column = {edge_row.at ({s[0], s[1]}), edge_row.at ({s[0], s[2]}),
                                         edge_row.at ({s[1], s[2]})};
    std::sort (column.begin (), column.end ());
    while (!column.empty ())
    {
      auto it = column_of_pivot.find (column.back ());
      if (it == column_of_pivot.end ())
      {
        column_of_pivot.emplace (column.back (), column);
        ++rank;
        break;
      }
      std::vector<std::uint32_t> sum; // symmetric difference = addition over GF(2)
      std::set_symmetric_difference (column.begin (), column.end (), it->second.begin (), it->second.end (),
                                     std::back_inserter (sum));
      column.swap (sum);
    }
  }
  return rank;
}

} // namespace

Homology
homology (const std::vector<Tuple>& complex)
{
  Homology h;
  UnionFind components;
  std::size_t vertices = 0, edges = 0;
  for (const auto& s : complex)
  {
    h.euler += s.size () % 2 == 1 ? 1 : -1;
    if (s.size () == 1)
    {
      components.find (s[0]);
      ++vertices;
    }
    if (s.size () == 2)
    {
      components.join (s[0], s[1]);
      ++edges;
    }
  }
  h.components = components.roots ();
  // beta_1 = dim ker d1 - rank d2, with rank d1 = V - beta_0.
  h.betti1 = edges - (vertices - h.components) - rankOfTriangleBoundary (complex);
  return h;
}

bool
closedUnderFaces (const std::vector<Tuple>& complex)
{
  const std::set<Tuple> all (complex.begin (), complex.end ());
  for (const auto& s : complex)
    for (unsigned mask = 1; mask + 1 < (1u << s.size ()); ++mask)
    {
      Tuple face;
      for (std::size_t i = 0; i < s.size (); ++i)
        if (mask & (1u << i))
          face.push_back (s[i]);
      if (!all.count (face))
        return false;
    }
  return true;
}

std::map<std::pair<std::uint32_t, std::uint32_t>, int>
edgeUses (const std::vector<Triangle>& triangles)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i)
      ++uses[std::minmax (t[i], t[(i + 1) % 3])];
  return uses;
}

bool
isOneCycle (const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges)
{
  UnionFind cycle;
  std::map<std::uint32_t, int> degree;
  for (const auto& [a, b] : edges)
  {
    cycle.join (a, b);
    ++degree[a];
    ++degree[b];
  }
  return !edges.empty () && cycle.roots () == 1 &&
         std::all_of (degree.begin (), degree.end (), [] (const auto& d) { return d.second == 2; });
}

SurfaceReport
describeSurface (const std::vector<Triangle>& triangles)
{
  SurfaceReport r;
  const auto uses = edgeUses (triangles);
  std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
  r.consistently_oriented = true;
  std::map<std::uint32_t, std::vector<std::pair<std::uint32_t, std::uint32_t>>> link; // vertex -> opposite edges
  UnionFind parts;
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i)
    {
      r.consistently_oriented &= directed.emplace (t[i], t[(i + 1) % 3]).second;
      link[t[i]].emplace_back (t[(i + 1) % 3], t[(i + 2) % 3]);
      parts.join (t[i], t[(i + 1) % 3]);
    }
  r.vertices = link.size ();
  r.edges = uses.size ();
  r.components = parts.roots ();
  r.euler = long (r.vertices) - long (r.edges) + long (triangles.size ());
  r.closed_manifold = std::all_of (uses.begin (), uses.end (), [] (const auto& u) { return u.second == 2; });
  // Every vertex link must be one cycle: connected, with every link vertex of degree 2.
  for (const auto& [v, edges] : link)
  {
    if (!r.closed_manifold)
      break;
    r.closed_manifold = isOneCycle (edges);
  }
  return r;
}

OpenSurfaceReport
describeOpenSurface (const std::vector<Triangle>& triangles)
{
  OpenSurfaceReport r;
  const auto uses = edgeUses (triangles);
  std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
  std::set<Triangle> distinct;
  std::map<std::uint32_t, std::vector<std::pair<std::uint32_t, std::uint32_t>>> link;
  UnionFind parts;
  r.consistently_oriented = true;
  for (const auto& t : triangles)
  {
    Triangle sorted = t;
    std::sort (sorted.begin (), sorted.end ());
    distinct.insert (sorted);
    for (int i = 0; i < 3; ++i)
    {
      r.consistently_oriented &= directed.emplace (t[i], t[(i + 1) % 3]).second;
      link[t[i]].emplace_back (t[(i + 1) % 3], t[(i + 2) % 3]);
      parts.join (t[i], t[(i + 1) % 3]);
    }
  }
  r.no_duplicate_triangles = distinct.size () == triangles.size ();
  r.vertices = link.size ();
  r.components = parts.roots ();
  std::map<std::uint32_t, std::size_t> component_size;
  for (const auto& entry : link)
    r.largest_component_vertices = std::max (r.largest_component_vertices, ++component_size[parts.find (entry.first)]);
  std::uint32_t largest = 0;
  for (const auto& [root, size] : component_size)
    if (size == r.largest_component_vertices)
      largest = root;
  long v = 0, e = 0, f = 0;
  for (const auto& entry : link)
    v += parts.find (entry.first) == largest;
  for (const auto& [edge, count] : uses)
    e += parts.find (edge.first) == largest;
  for (const auto& t : triangles)
    f += parts.find (t[0]) == largest;
  r.largest_component_euler = v - e + f;
  r.euler = long (r.vertices) - long (uses.size ()) + long (triangles.size ());
  r.manifold = true;
  for (const auto& [edge, count] : uses)
  {
    r.manifold &= count <= 2;
    r.boundary_edges += count == 1;
  }
  // A vertex link is one cycle (inside) or one path (on the boundary): connected, degrees <= 2,
  // and at most two link vertices of degree 1.
  for (const auto& [v, edges] : link)
  {
    UnionFind path;
    std::map<std::uint32_t, int> degree;
    for (const auto& [a, b] : edges)
    {
      path.join (a, b);
      ++degree[a];
      ++degree[b];
    }
    int ends = 0;
    for (const auto& [u, d] : degree)
    {
      r.manifold &= d <= 2;
      ends += d == 1;
    }
    r.manifold &= path.roots () == 1 && ends <= 2;
  }
  return r;
}

} // namespace pcl_wrap::test

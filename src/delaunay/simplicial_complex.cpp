// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "delaunay/simplicial_complex.h"
#include "util/portable.h"

#include "util/parallel_for_each.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>

namespace pcl_wrap::detail
{
namespace
{

/** When the top simplices (vertices \a top, d + 1 per simplex) each list their lowest vertex
  * first and come grouped by it in ascending order, as the triangulation gives its tetrahedra:
  * where each group starts, group[a] the first top simplex whose lowest vertex is a (or where it
  * would be), for a in [0, num_vertices]. Otherwise empty. */
std::vector<std::size_t>
groupsByLowestVertex (int d, std::uint32_t num_vertices, const FilledInParallel<std::uint32_t>& top)
{
  const std::size_t num_top = top.size () / (d + 1);
  const auto lowest = [&] (std::size_t t) { return top[(d + 1) * t]; };
  constexpr std::size_t NONE = ~std::size_t (0);
  std::vector<std::size_t> group (num_vertices + 1, NONE);
  std::atomic<bool> grouped{true};
  parallelForEach (num_top, [&] (std::size_t t) {
    for (int i = 1; i <= d; ++i)
      if (top[(d + 1) * t + i] <= lowest (t))
        grouped.store (false, std::memory_order_relaxed);
    if (t > 0 && lowest (t) < lowest (t - 1))
      grouped.store (false, std::memory_order_relaxed);
    else if (t == 0 || lowest (t) != lowest (t - 1))
      relaxedStore (&group[lowest (t)], t); // racing only when not grouped
  });
  if (!grouped.load ())
    return {};
  group[num_vertices] = num_top;
  for (std::size_t a = num_vertices; a-- > 0;)
    if (group[a] == NONE)
      group[a] = group[a + 1];
  return group;
}

/** Calls f on the items of two sorted ranges in their merged order. */
template <class ItA, class ItB, class F>
void
inMergedOrder (ItA a, ItA a_end, ItB b, ItB b_end, const F& f)
{
  while (a != a_end || b != b_end)
    f (b == b_end || (a != a_end && !(*b < *a)) ? *a++ : *b++);
}

/** Names the edges of the top simplices of a complex of dimension 2 or 3 (vertices \a top, d + 1
  * per simplex): fills \a edge_vertices (two per edge, ascending, edges in lexicographic order)
  * and \a top_edges (per top simplex, the id of its edge between local vertices (i, j), i < j,
  * in the order (0,1), (0,2), ...) and \a edge_tops (per edge, the number of top simplices on
  * it). Every edge instance is bucketed by its lower vertex with its slot in \a top_edges;
  * sorting a bucket brings an edge's instances together, and each takes the edge's id directly.
  * When the top simplices come grouped by their lowest vertex (groupsByLowestVertex), the edges
  * at that vertex are already together and skip the bucketing: half the instances of
  * tetrahedra. In parallel; the ids depend only on the set of edges. */
void
nameEdges (int d, std::uint32_t num_vertices, const FilledInParallel<std::uint32_t>& top,
           FilledInParallel<std::uint32_t>& edge_vertices, FilledInParallel<SimplexId>& top_edges,
           FilledInParallel<std::uint32_t>& edge_tops)
{
  const std::size_t num_top = top.size () / (d + 1), per_top = d == 3 ? 6 : 3;
  if (per_top * num_top > std::numeric_limits<std::uint32_t>::max ())
    throw std::length_error ("SimplicialComplex: too many simplices");
  struct Instance
  {
    std::uint32_t other; // the higher vertex
    std::uint32_t slot;  // in top_edges
    bool operator< (const Instance& o) const { return other < o.other; }
  };
  const std::vector<std::size_t> group = groupsByLowestVertex (d, num_vertices, top);
  const bool grouped = !group.empty ();
  const auto each = [&] (std::size_t t, auto put) {
    std::uint32_t slot = static_cast<std::uint32_t> (per_top * t);
    for (int i = 0; i <= d; ++i)
      for (int j = i + 1; j <= d; ++j, ++slot)
        if (i > 0 || !grouped)
        {
          const std::uint32_t a = top[(d + 1) * t + i], b = top[(d + 1) * t + j];
          put (std::min (a, b), Instance{std::max (a, b), slot});
        }
  };
  // Grouped, the edges (0, j) of the top simplices with lowest vertex a, sorted, in their place.
  FilledInParallel<Instance> at_lowest (grouped ? d * num_top : 0);
  const auto atLowest = [&] (std::size_t a) -> std::pair<Instance*, Instance*> {
    if (!grouped)
      return {nullptr, nullptr};
    return {at_lowest.data () + d * group[a], at_lowest.data () + d * group[a + 1]};
  };

  // A bucket's distinct edges are counted while it is in cache; a prefix sum gives each bucket
  // its first id.
  std::vector<SimplexId> first_id (num_vertices + 1, 0);
  std::vector<std::size_t> begin;
  const auto instances =
      bucketInParallel<Instance> (num_top, num_vertices, each, begin, [&] (std::size_t a, auto first, auto last) {
        std::sort (first, last);
        const auto [own, own_end] = atLowest (a);
        Instance* out = own;
        for (std::size_t t = grouped ? group[a] : 0; out != own_end; ++t)
          for (int j = 1; j <= d; ++j) // edge (0, j) is in slot j - 1
            *out++ = Instance{top[(d + 1) * t + j], static_cast<std::uint32_t> (per_top * t + j - 1)};
        std::sort (own, own_end);
        SimplexId distinct = 0;
        const Instance* previous = nullptr;
        inMergedOrder (first, last, own, own_end, [&] (const Instance& x) {
          distinct += previous == nullptr || x.other != previous->other;
          previous = &x;
        });
        first_id[a + 1] = distinct;
      });
  for (std::uint32_t a = 0; a < num_vertices; ++a)
    first_id[a + 1] += first_id[a];

  edge_vertices.resize (2 * std::size_t (first_id[num_vertices]));
  top_edges.resize (per_top * num_top);
  edge_tops.resize (first_id[num_vertices]);
  parallelForEach (num_vertices, [&] (std::size_t a) {
    SimplexId next = first_id[a], id = NO_SIMPLEX;
    const Instance* previous = nullptr;
    const auto [own, own_end] = atLowest (a);
    inMergedOrder (instances.data () + begin[a], instances.data () + begin[a + 1], own, own_end,
                   [&] (const Instance& x) {
                     if (previous == nullptr || x.other != previous->other)
                     {
                       id = next++;
                       edge_vertices[2 * std::size_t (id)] = static_cast<std::uint32_t> (a);
                       edge_vertices[2 * std::size_t (id) + 1] = x.other;
                       edge_tops[id] = 0;
                     }
                     previous = &x;
                     top_edges[x.slot] = id;
                     ++edge_tops[id]; // the bucket's own edge: no other thread counts it
                   });
  });
}

void
sort3 (std::uint32_t& a, std::uint32_t& b, std::uint32_t& c)
{
  if (a > b) std::swap (a, b);
  if (b > c) std::swap (b, c);
  if (a > b) std::swap (a, b);
}

} // namespace

SimplicialComplex::SimplicialComplex (int dimension, std::uint32_t num_vertices, FilledInParallel<std::uint32_t> top,
                                      const FilledInParallel<std::uint32_t>& neighbours)
  : dimension_ (dimension)
{
  if (dimension < -1 || dimension > 3 || (dimension >= 0 && top.size () % (dimension + 1) != 0))
    throw std::invalid_argument ("SimplicialComplex: bad dimension or top simplex list");
  if (dimension == -1)
    return;
  vertices_[0].resize (num_vertices);
  for (std::uint32_t v = 0; v < num_vertices; ++v)
    vertices_[0][v] = v;
  if (dimension == 0)
  {
    cofaces_[0].assign (num_vertices, 0);
    return;
  }

  const std::size_t num_top = top.size () / (dimension + 1);
  if (dimension == 1)
  {
    for (std::size_t e = 0; e < num_top; ++e)
      if (top[2 * e] > top[2 * e + 1])
        std::swap (top[2 * e], top[2 * e + 1]);
    vertices_[1] = std::move (top);
    cofaces_[1].assign (size (1), 0);
    countEdgesOfVertices ();
    return;
  }

  // dimension 2 or 3: the edges (and, in 3, the triangles) are the faces of the top simplices.
  const int d = dimension;
  if (d == 2)
  {
    for (std::size_t t = 0; t < num_top; ++t)
      sort3 (top[3 * t], top[3 * t + 1], top[3 * t + 2]);
    FilledInParallel<SimplexId> pair_edges; // edges (0,1), (0,2), (1,2): opposite local vertex 2, 1, 0
    nameEdges (d, num_vertices, top, vertices_[1], pair_edges, cofaces_[1]);
    vertices_[2] = std::move (top);
    triangle_edges_.resize (3 * size (2));
    parallelForEach (size (2), [&] (std::size_t t) {
      for (int i = 0; i < 3; ++i)
        triangle_edges_[3 * t + i] = pair_edges[3 * t + 2 - i];
    });
    cofaces_[2].assign (size (2), 0);
  }
  else
  {
    // A triangle is named once, by the first of its two tetrahedra (or its only one, on the
    // hull), and the tetrahedron across learns its name through the neighbour relation. Ids
    // follow the tetrahedra: fillInOrder gives each its first one.
    if (neighbours.size () != top.size ())
      throw std::invalid_argument ("SimplicialComplex: tetrahedra need their neighbours");
    const auto names = [&] (std::size_t t, int i) {
      const std::uint32_t u = neighbours[4 * t + i];
      return u == ~std::uint32_t (0) || u > t;
    };
    nameEdges (d, num_vertices, top, vertices_[1], tet_edges_, cofaces_[1]);
    tet_triangles_.resize (4 * num_top);
    parallelForEach (tet_triangles_.size (), [&] (std::size_t k) { tet_triangles_[k] = NO_SIMPLEX; });
    std::vector<std::uint8_t> on_hull (size (1), 0); // edges of a triangle with one tetrahedron
    const auto count = [&] (std::size_t t) { return names (t, 0) + names (t, 1) + names (t, 2) + names (t, 3); };
    const auto resize = [&] (std::size_t triangles) {
      vertices_[2].resize (3 * triangles);
      triangle_edges_.resize (3 * triangles);
      cofaces_[2].resize (triangles);
    };
    fillInOrder (num_top, count, resize, [&] (std::size_t t, std::size_t next) {
      const std::uint32_t* v = &top[4 * t];
      const SimplexId* edge = &tet_edges_[6 * t];
      for (int i = 0; i < 4; ++i)
      {
        if (!names (t, i))
          continue;
        const auto f = static_cast<SimplexId> (next++);
        // The facet's local vertices in ascending vertex id; its edges are the tetrahedron's.
        int l[3] = {(i + 1) % 4, (i + 2) % 4, (i + 3) % 4};
        std::sort (l, l + 3, [&] (int x, int y) { return v[x] < v[y]; });
        for (int j = 0; j < 3; ++j)
        {
          vertices_[2][3 * std::size_t (f) + j] = v[l[j]];
          const unsigned opposite_j = (1u << l[(j + 1) % 3]) | (1u << l[(j + 2) % 3]);
          triangle_edges_[3 * std::size_t (f) + j] = edge[EDGE_SLOT[opposite_j]];
        }
        tet_triangles_[4 * t + i] = f;
        const std::uint32_t u = neighbours[4 * t + i];
        if (u == ~std::uint32_t (0))
        {
          cofaces_[2][f] = 1;
          for (int j = 0; j < 3; ++j) // several hull triangles may mark an edge: relaxed stores
            relaxedStore (&on_hull[triangle_edges_[3 * std::size_t (f) + j]], std::uint8_t (1));
          continue;
        }
        cofaces_[2][f] = 2;
        int j = 0;
        while (j < 4 && neighbours[4 * std::size_t (u) + j] != t)
          ++j;
        if (j == 4)
          throw std::invalid_argument ("SimplicialComplex: neighbour relation not symmetric");
        tet_triangles_[4 * std::size_t (u) + j] = f;
      }
      return next;
    });
    if (std::find (tet_triangles_.begin (), tet_triangles_.end (), NO_SIMPLEX) != tet_triangles_.end ())
      throw std::invalid_argument ("SimplicialComplex: neighbour relation not symmetric");
    vertices_[3] = std::move (top);
    // Around an edge inside the hull, tetrahedra and triangles alternate in a closed ring; on
    // the hull the ring is open, with one triangle more.
    parallelForEach (size (1), [&] (std::size_t e) { cofaces_[1][e] += on_hull[e]; });
  }
  countEdgesOfVertices ();
}

void
SimplicialComplex::countEdgesOfVertices ()
{
  std::vector<std::atomic<std::uint32_t>> edges (size (0));
  parallelForEach (size (1), [&] (std::size_t e) {
    for (int i = 0; i < 2; ++i)
      edges[vertices_[1][2 * e + i]].fetch_add (1, std::memory_order_relaxed);
  });
  cofaces_[0].resize (size (0));
  parallelForEach (size (0), [&] (std::size_t v) { cofaces_[0][v] = edges[v].load (std::memory_order_relaxed); });
}

} // namespace pcl_wrap::detail

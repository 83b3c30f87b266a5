// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "simplicial_complex.h"

#include "parallel_for_each.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace pcl_wrap::detail
{
namespace
{

// Local vertex pairs of a tetrahedron's six edges, and the slot of each two-bit mask.
constexpr int TET_EDGE[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
constexpr int EDGE_SLOT[16] = {-1, -1, -1, 0, -1, 1, 3, -1, -1, 2, 4, -1, 5, -1, -1, -1};

/** Faces of one dimension, bucketed by their lowest vertex: a face is found by a binary search
  * among the few faces of its lowest vertex, and its id is its position in the table. Built in
  * parallel; the table depends only on the set of faces, not on the threads. */
template <class Key>
class FaceTable
{
public:
  /** \a each(i, emit) calls emit(lowest vertex, key of the other vertices) for the face
    * instances of top simplex \a i. */
  template <class Enumerate>
  FaceTable (std::uint32_t num_vertices, std::size_t num_top, const Enumerate& each)
    : begin_ (num_vertices + 1, 0)
  {
    std::vector<std::atomic<std::size_t>> fill (num_vertices + 1);
    parallelForEach (num_top, [&] (std::size_t i) {
      each (i, [&] (std::uint32_t a, Key) { fill[a + 1].fetch_add (1, std::memory_order_relaxed); });
    });
    for (std::uint32_t a = 0; a < num_vertices; ++a)
      begin_[a + 1] = begin_[a] + fill[a + 1].load (std::memory_order_relaxed);
    keys_.resize (begin_[num_vertices]);
    for (std::uint32_t a = 0; a < num_vertices; ++a)
      fill[a].store (begin_[a], std::memory_order_relaxed);
    parallelForEach (num_top, [&] (std::size_t i) {
      each (i, [&] (std::uint32_t a, Key k) { keys_[fill[a].fetch_add (1, std::memory_order_relaxed)] = k; });
    });

    // Sort and deduplicate each bucket in place, then close the gaps.
    std::vector<std::size_t> unique (num_vertices + 1, 0);
    parallelForEach (num_vertices, [&] (std::size_t a) {
      auto first = keys_.begin () + begin_[a], last = keys_.begin () + begin_[a + 1];
      std::sort (first, last);
      unique[a + 1] = static_cast<std::size_t> (std::unique (first, last) - first);
    });
    for (std::uint32_t a = 0; a < num_vertices; ++a)
      unique[a + 1] += unique[a];
    std::vector<Key> packed (unique[num_vertices]);
    parallelForEach (num_vertices, [&] (std::size_t a) {
      std::copy_n (keys_.begin () + begin_[a], unique[a + 1] - unique[a], packed.begin () + unique[a]);
    });
    keys_ = std::move (packed);
    begin_ = std::move (unique);
  }

  std::size_t size () const { return keys_.size (); }
  std::size_t begin (std::uint32_t a) const { return begin_[a]; }
  std::size_t end (std::uint32_t a) const { return begin_[a + 1]; }
  Key key (std::size_t f) const { return keys_[f]; }

  SimplexId find (std::uint32_t a, Key k) const
  {
    auto first = keys_.begin () + begin_[a], last = keys_.begin () + begin_[a + 1];
    auto it = std::lower_bound (first, last, k);
    if (it == last || *it != k)
      throw std::logic_error ("SimplicialComplex: face of a simplex not found");
    return static_cast<SimplexId> (it - keys_.begin ());
  }

private:
  std::vector<std::size_t> begin_;
  std::vector<Key> keys_;
};

void
sort3 (std::uint32_t& a, std::uint32_t& b, std::uint32_t& c)
{
  if (a > b) std::swap (a, b);
  if (b > c) std::swap (b, c);
  if (a > b) std::swap (a, b);
}

} // namespace

SimplicialComplex::SimplicialComplex (int dimension, std::uint32_t num_vertices,
                                      std::vector<std::uint32_t> top, const std::vector<std::uint32_t>& neighbours)
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
    return;

  const std::size_t num_top = top.size () / (dimension + 1);
  if (dimension == 1)
  {
    for (std::size_t e = 0; e < num_top; ++e)
      if (top[2 * e] > top[2 * e + 1])
        std::swap (top[2 * e], top[2 * e + 1]);
    vertices_[1] = std::move (top);
    return;
  }

  // dimension 2 or 3: the edges (and, in 3, the triangles) are the faces of the top simplices.
  const int d = dimension;
  const FaceTable<std::uint32_t> edges (num_vertices, num_top, [&] (std::size_t t, auto emit) {
    for (int i = 0; i <= d; ++i)
      for (int j = i + 1; j <= d; ++j)
      {
        std::uint32_t a = top[(d + 1) * t + i], b = top[(d + 1) * t + j];
        emit (std::min (a, b), std::max (a, b));
      }
  });
  vertices_[1].resize (2 * edges.size ());
  parallelForEach (num_vertices, [&] (std::size_t a) {
    for (std::size_t f = edges.begin (a); f < edges.end (a); ++f)
    {
      vertices_[1][2 * f] = static_cast<std::uint32_t> (a);
      vertices_[1][2 * f + 1] = edges.key (f);
    }
  });
  const auto edge_id = [&] (std::uint32_t a, std::uint32_t b) {
    return edges.find (std::min (a, b), std::max (a, b));
  };

  if (d == 2)
  {
    for (std::size_t t = 0; t < num_top; ++t)
      sort3 (top[3 * t], top[3 * t + 1], top[3 * t + 2]);
    vertices_[2] = std::move (top);
    triangle_edges_.resize (3 * size (2));
    parallelForEach (size (2), [&] (std::size_t t) {
      const std::uint32_t* v = vertices (2, static_cast<SimplexId> (t));
      triangle_edges_[3 * t + 0] = edge_id (v[1], v[2]);
      triangle_edges_[3 * t + 1] = edge_id (v[0], v[2]);
      triangle_edges_[3 * t + 2] = edge_id (v[0], v[1]);
    });
  }
  else
  {
    // A triangle is named once, by the first of its two tetrahedra (or its only one, on the
    // hull), and the tetrahedron across learns its name through the neighbour relation. A
    // prefix sum over the tetrahedra gives each its first triangle id.
    if (neighbours.size () != top.size ())
      throw std::invalid_argument ("SimplicialComplex: tetrahedra need their neighbours");
    const auto names = [&] (std::size_t t, int i) {
      const std::uint32_t u = neighbours[4 * t + i];
      return u == ~std::uint32_t (0) || u > t;
    };
    std::vector<SimplexId> first_triangle (num_top + 1, 0);
    for (std::size_t t = 0; t < num_top; ++t)
      first_triangle[t + 1] = first_triangle[t] + names (t, 0) + names (t, 1) + names (t, 2) + names (t, 3);
    vertices_[2].resize (3 * std::size_t (first_triangle[num_top]));
    tet_triangles_.assign (4 * num_top, NO_SIMPLEX);
    tet_edges_.resize (6 * num_top);
    triangle_edges_.resize (vertices_[2].size ());
    parallelForEach (num_top, [&] (std::size_t t) {
      const std::uint32_t* v = &top[4 * t];
      const SimplexId* edge = &tet_edges_[6 * t];
      for (int e = 0; e < 6; ++e)
        tet_edges_[6 * t + e] = edge_id (v[TET_EDGE[e][0]], v[TET_EDGE[e][1]]);
      SimplexId next = first_triangle[t];
      for (int i = 0; i < 4; ++i)
      {
        if (!names (t, i))
          continue;
        const SimplexId f = next++;
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
          continue;
        int j = 0;
        while (j < 4 && neighbours[4 * std::size_t (u) + j] != t)
          ++j;
        if (j == 4)
          throw std::invalid_argument ("SimplicialComplex: neighbour relation not symmetric");
        tet_triangles_[4 * std::size_t (u) + j] = f;
      }
    });
    if (std::find (tet_triangles_.begin (), tet_triangles_.end (), NO_SIMPLEX) != tet_triangles_.end ())
      throw std::invalid_argument ("SimplicialComplex: neighbour relation not symmetric");
    vertices_[3] = std::move (top);
  }
}

Simplex
SimplicialComplex::face (int k, SimplexId s, unsigned mask) const
{
  const int n = maskSize (mask);
  if (n == k + 1)
    return {k, s};
  if (n == 1)
    return {0, vertex (k, s, __builtin_ctz (mask))};
  if (k == 3)
  {
    if (n == 3)
      return {2, tet_triangles_[4 * std::size_t (s) + __builtin_ctz (~mask & 15u)]};
    return {1, tet_edges_[6 * std::size_t (s) + EDGE_SLOT[mask]]};
  }
  // k == 2, n == 2
  return {1, triangle_edges_[3 * std::size_t (s) + __builtin_ctz (~mask & 7u)]};
}

} // namespace pcl_wrap::detail

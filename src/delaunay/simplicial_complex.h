// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/filled_in_parallel.h"
#include "util/portable.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Index of a simplex among those of its dimension. */
using SimplexId = std::uint32_t;
constexpr SimplexId NO_SIMPLEX = ~SimplexId (0);

/** \brief A simplex named by its dimension and its index in that dimension. Aligned as one 8-byte
  * word, so that atomic operations on it compile to single instructions. */
struct alignas (8) Simplex
{
  int dim;
  SimplexId id;
  bool operator== (const Simplex& o) const { return dim == o.dim && id == o.id; }
};

/** \brief The Delaunay complex in flat arrays, indexed by simplex id per dimension.
  *
  * Faces of a k-simplex are named by a *mask* over its k+1 local vertices (bit i = local vertex
  * i), so that a simplex and all its faces are reached in O(1) without any search. Tetrahedra
  * keep the triangulation's positive orientation; lower simplices list their vertices in
  * ascending order. Vertex ids are dense, 0..numVertices()-1.
  */
class SimplicialComplex
{
public:
  /** \brief Builds the complex of dimension \a dimension whose top simplices are given, (d+1)
    * vertex ids each (tetrahedra positively oriented). Every face is created once.
    * \param[in] neighbours dimension 3: per tetrahedron, the tetrahedron across the facet
    *            opposite each local vertex, or ~0 on the hull (see Triangulation) */
  SimplicialComplex (int dimension, std::uint32_t num_vertices, FilledInParallel<std::uint32_t> top_simplices,
                     const FilledInParallel<std::uint32_t>& neighbours = {});
  SimplicialComplex () = default;

  int dimension () const { return dimension_; }
  std::size_t size (int k) const { return k < 0 || k > 3 ? 0 : vertices_[k].size () / (k + 1); }
  std::uint32_t numVertices () const { return static_cast<std::uint32_t> (size (0)); }

  /** \brief The k+1 vertex ids of simplex \a s of dimension \a k (a valid pointer to no simplex
   *  when \a s is size (k)). */
  const std::uint32_t* vertices (int k, SimplexId s) const { return vertices_[k].data () + (k + 1) * std::size_t (s); }
  std::uint32_t vertex (int k, SimplexId s, int i) const { return vertices (k, s)[i]; }
  /** \brief The vertex ids of all simplices of dimension \a k, k + 1 per simplex. */
  const FilledInParallel<std::uint32_t>& vertexArray (int k) const { return vertices_[k]; }

  /** \brief Per simplex of dimension \a k (0 to 2): how many simplices of dimension k + 1 have it
    * as a face. */
  const FilledInParallel<std::uint32_t>& cofaceCounts (int k) const { return cofaces_[k]; }
  /** \brief Hands the coface counts over (to a retraction, which would copy them otherwise);
    * cofaceCounts() is empty afterwards. */
  std::array<FilledInParallel<std::uint32_t>, 3> releaseCofaceCounts () { return std::exchange (cofaces_, {}); }

  /** \brief The face of simplex (k, s) spanned by the local vertices in \a mask (non-empty). */
  Simplex face (int k, SimplexId s, unsigned mask) const;
  /** \brief The facet of simplex (k, s), k >= 1, opposite its local vertex \a i. */
  Simplex facet (int k, SimplexId s, int i) const;

private:
  /** Fills cofaces_[0] from the edges. */
  void countEdgesOfVertices ();

  int dimension_ = -1;
  std::array<FilledInParallel<std::uint32_t>, 4> vertices_;
  FilledInParallel<SimplexId> tet_triangles_;  // 4 per tetrahedron, opposite local vertex i
  FilledInParallel<SimplexId> tet_edges_;      // 6 per tetrahedron, see EDGE_SLOT
  FilledInParallel<SimplexId> triangle_edges_; // 3 per triangle, opposite local vertex i
  std::array<FilledInParallel<std::uint32_t>, 3> cofaces_; // see cofaceCounts()
};

/** \brief Number of local vertices in a mask. */
inline int
maskSize (unsigned mask)
{
  // Masks have at most four bits; a nibble table, as the default target has no popcount.
  return static_cast<int> ((0x4332322132212110ull >> (4 * (mask & 15u))) & 15u);
}

/** \brief The mask of all k+1 local vertices of a k-simplex. */
inline unsigned
fullMask (int k)
{
  return (1u << (k + 1)) - 1u;
}

/** \brief A tetrahedron's six edges are kept in the order of their local vertex pairs (0,1),
  * (0,2), (0,3), (1,2), (1,3), (2,3); the slot of each two-bit mask. */
inline constexpr int EDGE_SLOT[16] = {-1, -1, -1, 0, -1, 1, 3, -1, -1, 2, 4, -1, 5, -1, -1, -1};

inline Simplex
SimplicialComplex::face (int k, SimplexId s, unsigned mask) const
{
  const int n = maskSize (mask);
  if (n == k + 1)
    return {k, s};
  if (n == 1)
    return {0, vertex (k, s, lowestSetBit (mask))};
  if (k == 3)
  {
    if (n == 3)
      return {2, tet_triangles_[4 * std::size_t (s) + lowestSetBit (~mask & 15u)]};
    return {1, tet_edges_[6 * std::size_t (s) + EDGE_SLOT[mask]]};
  }
  // k == 2, n == 2
  return {1, triangle_edges_[3 * std::size_t (s) + lowestSetBit (~mask & 7u)]};
}

inline Simplex
SimplicialComplex::facet (int k, SimplexId s, int i) const
{
  return face (k, s, fullMask (k) & ~(1u << i));
}

} // namespace pcl_wrap::detail

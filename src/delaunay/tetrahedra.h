// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/simplicial_complex.h"
#include "util/filled_in_parallel.h"
#include "util/portable.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Across a facet of the convex hull: no tetrahedron, the outside for good. */
constexpr std::uint32_t OUTSIDE_HULL = ~std::uint32_t (0);
/** \brief No tetrahedron (of a vertex on none). */
constexpr std::uint32_t NO_TETRAHEDRON = ~std::uint32_t (0);

/** \brief The tetrahedra around one vertex, gathered by Tetrahedra::gatherStar(). Reused from star
  * to star by one thread, so that gathering allocates nothing once warm; each thread that gathers
  * stars has its own. */
class Star
{
public:
  Star () : keys_ (256, NOT_IN_STAR), slots_ (256) {}

  static constexpr std::uint32_t NOT_IN_STAR = ~std::uint32_t (0);

  std::uint32_t vertex () const { return vertex_; }
  /** \brief The tetrahedra, in the order they were found. */
  const std::vector<std::uint32_t>& tetrahedra () const { return tetrahedra_; }
  std::size_t size () const { return tetrahedra_.size (); }
  bool empty () const { return tetrahedra_.empty (); }
  std::uint32_t operator[] (std::size_t k) const { return tetrahedra_[k]; }
  /** \brief Where tetrahedron \a t is in tetrahedra(), or NOT_IN_STAR. */
  std::uint32_t indexOf (std::uint32_t t) const;

private:
  friend class Tetrahedra;
  void clear (std::uint32_t vertex);
  /** Appends \a t unless it is there already; returns whether it was new. */
  bool add (std::uint32_t t);
  std::uint32_t mask () const { return static_cast<std::uint32_t> (keys_.size () - 1); }
  std::uint32_t home (std::uint32_t t) const { return (t * 2654435761u) >> 8 & mask (); }
  void grow ();

  std::uint32_t vertex_ = 0;
  std::vector<std::uint32_t> tetrahedra_;
  // A small open-addressing table from tetrahedron to its place, emptied in the time it was filled.
  std::vector<std::uint32_t> keys_, slots_, used_;
};

/** \brief The tetrahedra of Del S and how they meet: the tetrahedron across each facet, the facet
  * it is seen through from there, and the tetrahedra around a vertex; what a triangulation data
  * structure such as CGAL's gives (neighbor, mirror_index, incident_cells), over flat arrays.
  *
  * It starts from the triangulation's neighbour array, before the complex is built (the default
  * surface's votes and flood need only that); attach() adds the complex, whose tetrahedra are the
  * same, for their vertices and the stars. */
class Tetrahedra
{
public:
  Tetrahedra () = default;
  /** \param[in] neighbours per tetrahedron, the tetrahedron across the facet opposite each of its
    *            vertex slots, or OUTSIDE_HULL */
  explicit Tetrahedra (FilledInParallel<std::uint32_t> neighbours);

  /** \brief The complex built on the same tetrahedra; finds each vertex's highest-numbered
    * tetrahedron, where its star is gathered from, on all threads. */
  void attach (const SimplicialComplex& complex);

  std::size_t size () const { return neighbours_.size () / 4; }
  /** \brief The tetrahedron across facet \a i of \a t (opposite its vertex i), or OUTSIDE_HULL. */
  std::uint32_t neighbour (std::uint32_t t, int i) const { return neighbours_[4 * std::size_t (t) + i]; }
  /** \brief Does a facet of \a t lie on the convex hull? */
  bool onHull (std::uint32_t t) const
  {
    const std::uint32_t* across = &neighbours_[4 * std::size_t (t)];
    return across[0] == OUTSIDE_HULL || across[1] == OUTSIDE_HULL || across[2] == OUTSIDE_HULL ||
           across[3] == OUTSIDE_HULL;
  }
  /** \brief The facet of neighbour (t, i) through which it sees \a t. */
  int mirrorIndex (std::uint32_t t, int i) const
  {
    const std::uint32_t* across = &neighbours_[4 * std::size_t (neighbour (t, i))];
    int j = 0;
    while (across[j] != t)
      ++j;
    return j;
  }
  /** \brief Per tetrahedron, its four neighbours: the array the complex is built from. */
  const FilledInParallel<std::uint32_t>& neighbourArray () const { return neighbours_; }

  /** \name After attach() */
  ///@{
  const SimplicialComplex& complex () const { return *complex_; }
  std::uint32_t vertex (std::uint32_t t, int i) const { return complex_->vertex (3, t, i); }
  const std::uint32_t* vertices (std::uint32_t t) const { return complex_->vertices (3, t); }
  /** \brief The vertices of the tetrahedra \a ids, ascending, each once. */
  std::vector<std::uint32_t> verticesOf (const std::vector<std::uint32_t>& ids) const;
  /** \brief Where \a v is among \a t's vertices, which must hold it. */
  int localIndex (std::uint32_t t, std::uint32_t v) const
  {
    const std::uint32_t* a = vertices (t);
    return a[0] == v ? 0 : a[1] == v ? 1 : a[2] == v ? 2 : 3;
  }
  bool hasVertex (std::uint32_t t, std::uint32_t v) const
  {
    const std::uint32_t* a = vertices (t);
    return a[0] == v || a[1] == v || a[2] == v || a[3] == v;
  }
  /** \brief Of \a t's two facets that hold the edge (v, w), the one that is not facet \a i: where
    * a walk round the edge leaves t when it came in through facet i. */
  int otherFacetRoundEdge (std::uint32_t t, int i, std::uint32_t v, std::uint32_t w) const
  {
    int out = 0;
    while (out == i || vertex (t, out) == v || vertex (t, out) == w)
      ++out;
    return out;
  }
  /** \brief Does \a pred hold for some tetrahedron around the edge of \a t between its local
    * vertices \a a and \a b (t among them)? The ring is walked from t one way round, and the
    * other way when the hull stops it. */
  template <class Pred>
  bool anyRoundEdge (std::uint32_t t, int a, int b, const Pred& pred) const
  {
    if (pred (t))
      return true;
    const std::uint32_t v = vertex (t, a), w = vertex (t, b);
    int first = 0;
    while (first == a || first == b)
      ++first;
    for (int leave : {first, otherFacetRoundEdge (t, first, v, w)})
      for (std::uint32_t at = t;;)
      {
        const std::uint32_t u = neighbour (at, leave);
        if (u == OUTSIDE_HULL)
          break;
        if (u == t)
          return false;
        if (pred (u))
          return true;
        leave = otherFacetRoundEdge (u, mirrorIndex (at, leave), v, w);
        at = u;
      }
    return false;
  }
  /** \brief The highest-numbered tetrahedron of \a v, or NO_TETRAHEDRON for a vertex of none. */
  std::uint32_t tetrahedronOf (std::uint32_t v) const { return tetrahedron_of_vertex_[v]; }
  /** \brief \a star := the tetrahedra that contain \a v, breadth first from tetrahedronOf (v)
    * across the facets that contain v, each in the order of its facets: an order that depends on
    * the triangulation alone. */
  void gatherStar (std::uint32_t v, Star& star) const;
  /** \brief Starts fetching what gatherStar (\a v) reads first, for a caller that knows which
    * star it gathers next. */
  void prefetchStar (std::uint32_t v) const
  {
    const std::uint32_t t = tetrahedronOf (v);
    if (t != NO_TETRAHEDRON)
      prefetchTetrahedron (t);
  }
  /** \brief The face of Del S with the \a n vertices \a v, found in the star of \a around (one of
    * them), gathered into \a star: a tetrahedron that has them all, and the mask of their local
    * indices in it; {NO_TETRAHEDRON, 0} if none has. */
  std::pair<std::uint32_t, unsigned> faceAround (std::uint32_t around, const std::uint32_t* v, int n, Star& star) const;
  ///@}

private:
  /** Starts fetching what a star search reads of \a t: its neighbours and its vertices. */
  void prefetchTetrahedron (std::uint32_t t) const
  {
    prefetch (&neighbours_[4 * std::size_t (t)]);
    prefetch (vertices (t));
  }

  FilledInParallel<std::uint32_t> neighbours_;
  const SimplicialComplex* complex_ = nullptr;
  FilledInParallel<std::uint32_t> tetrahedron_of_vertex_;
};

} // namespace pcl_wrap::detail

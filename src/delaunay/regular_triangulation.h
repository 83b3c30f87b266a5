// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/filled_in_parallel.h"

#include <pcl_wrap/compute_wrap.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The regular triangulation of a set of weighted points, as plain arrays.
  *
  * Built by CGAL's Regular_triangulation_3 with exact predicates. Vertex ids are dense and
  * number the points that are vertices of the triangulation along a Z-order curve.
  */
struct Triangulation
{
  int dimension = -1;                    ///< -1 (no point), 0, 1, 2 or 3
  std::vector<std::uint32_t> point_of_vertex; ///< vertex id -> index into the given points
  std::vector<std::uint32_t> hidden;     ///< indices of points with an empty power cell
  /** \brief (dimension+1) vertex ids per top-dimensional simplex; tetrahedra positively
    * oriented. */
  FilledInParallel<std::uint32_t> top_simplices;
  /** \brief Dimension 3 only: per tetrahedron, the tetrahedron across the facet opposite each
    * local vertex (index into the tetrahedra), or NO_NEIGHBOUR on the hull. */
  FilledInParallel<std::uint32_t> neighbours;
};

constexpr std::uint32_t NO_NEIGHBOUR = ~std::uint32_t (0);

/** \brief The even permutation of a tetrahedron's local vertices (ids \a v) that puts its smallest
  * vertex id first and the next smallest second: one canonical, still positively oriented, order,
  * in which triangulate() lists each tetrahedron's vertices. */
std::array<int, 4>
canonicalOrder (const std::uint32_t* v);

/** \brief The order in which triangulate() lists tetrahedra (four vertex ids each, in
  * canonicalOrder(), below \a num_vertices): by their vertex sets, lowest vertex first. It depends
  * only on the vertex ids, not on CGAL's cells or the threads, and keeps the tetrahedra of a
  * neighbourhood together (the ids follow a space-filling curve). Returns the index of the r-th. */
FilledInParallel<std::uint32_t>
tetrahedronOrder (const FilledInParallel<std::uint32_t>& vertices, std::size_t num_vertices);

/** \brief Triangulates distinct, finite weighted points. With \a progress, a large input is
  * inserted in rounds, each a stretch of the points' Z-order curve (the triangulation is the
  * same), and \a progress is told the share inserted after each. The top simplices come in an
  * order that depends only on their vertex ids: tetrahedronOrder() when they span space, else by
  * vertex set. */
Triangulation
triangulate (const std::vector<Point3>& positions, const std::vector<double>& weights,
             const std::function<void (double)>& progress = {});

/** \brief A regular triangulation that points join in batches, read after each as triangulate()
  * would give it for all the points so far (the same tetrahedra, vertex ids and order when they
  * span space). For a process that learns its points in rounds: each batch costs its own
  * insertions, not a new triangulation. */
class GrowingTriangulation
{
public:
  /** \param[in] equal_weights every point of every batch has the same weight (then the
    *            triangulation is Delaunay's, built faster) */
  explicit GrowingTriangulation (bool equal_weights);
  ~GrowingTriangulation ();
  GrowingTriangulation (const GrowingTriangulation&) = delete;
  GrowingTriangulation& operator= (const GrowingTriangulation&) = delete;

  /** \brief Inserts the distinct, finite points \a positions[first..] (point i keeps index i). */
  void insert (const std::vector<Point3>& positions, const std::vector<double>& weights, std::size_t first);
  /** \brief The triangulation of \a positions, every one of which was inserted. */
  Triangulation read (const std::vector<Point3>& positions) const;
  /** \brief The edges of the triangulation, each once as the indices of its points (lower first),
    * in no set order: its graph, at a fraction of read()'s memory. */
  std::vector<std::array<std::uint32_t, 2>> edges () const;

  struct State
  {
    virtual ~State () = default;
    virtual void insert (const std::vector<Point3>& positions, const std::vector<double>& weights,
                         std::size_t first) = 0;
    virtual Triangulation read (const std::vector<Point3>& positions) const = 0;
    virtual std::vector<std::array<std::uint32_t, 2>> edges () const = 0;
  };

private:
  bool equal_weights_;
  std::unique_ptr<State> state_; // made by the first insertion, which knows its size
};

} // namespace pcl_wrap::detail

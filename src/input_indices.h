// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "wrap/boundary.h"
#include "wrap/classification.h"
#include "wrap/manifold_split.h"
#include "wrap/subcomplex.h"
#include "delaunay/simplicial_complex.h"

#include <pcl_wrap/wrap_result.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The one map from the engine's vertex ids to the caller's point indices. Vertex v is
  * input point (*this)(v); copies that the pinch split makes are appended as new vertices and
  * numbered after the input points. Every index that leaves the engine goes through it. */
class InputIndices
{
public:
  InputIndices () = default;
  explicit InputIndices (std::vector<PointIndex> of_vertex)
    : of_vertex_ (std::move (of_vertex)), vertices_ (of_vertex_.size ())
  {}

  PointIndex operator() (std::uint32_t vertex) const { return of_vertex_[vertex]; }
  std::size_t size () const { return of_vertex_.size (); }

  /** \brief Takes the pinch split \a split of \a w: its triangles become w's, vertex size() + k
    * becomes a copy of vertex split.copy_of[k], numbered \a input_points + k, the input point each
    * copy copies goes to WrapResult::copies, and the split's counts to the statistics of
    * \a result. */
  void takeSplit (ManifoldSplit& split, Boundary& w, std::size_t input_points, WrapResult& result);

  /** \brief \a w in point indices. */
  WrapSurface surface (const Boundary& w) const;

  /** \brief Sets WrapResult::off_surface of \a result and its count: the points of the vertices
    * (not the copies) that no triangle of result.surface has, in ascending order. The surface
    * numbers copy k \a input_points + k, a copy of result.copies[k]. */
  void recordPointsOff (WrapResult& result, std::size_t input_points) const;

  /** \brief The points that \a vertices are, in ascending order. */
  std::vector<PointIndex> sortedPoints (const std::vector<std::uint32_t>& vertices) const;

  /** \brief The complex in point indices, with each simplex's class and membership in \a x. */
  std::array<SimplexList, 4> complex (const SimplicialComplex& complex, const Classification& classification,
                                      const Subcomplex& x) const;

  /** \brief The same map with every point index i read as \a index (i). */
  InputIndices reindexed (const std::function<std::uint32_t (std::uint32_t)>& index) const;

private:
  std::vector<PointIndex> of_vertex_;
  std::size_t vertices_ = 0; ///< the vertices; the copies that takeSplit() appends follow them
};

} // namespace pcl_wrap::detail

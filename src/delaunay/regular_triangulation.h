// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/filled_in_parallel.h"

#include <pcl_wrap/compute_wrap.h>

#include <cstdint>
#include <functional>
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

/** \brief Triangulates distinct, finite weighted points. With \a progress, a large input is
  * inserted in rounds, each a random sample of the points (the triangulation is the same), and
  * \a progress is told the share inserted after each. */
Triangulation
triangulate (const std::vector<Point3>& positions, const std::vector<double>& weights,
             const std::function<void (double)>& progress = {});

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Per vertex, the squared distance to the nearest vertex sharing a simplex with it
  * (infinity for none), for \a count simplices of \a dimension (>= 1) given by their vertex ids
  * (dimension + 1 each); found on all threads. Each distance is computed alike from either end, so
  * any subset of the simplices around a vertex that holds its nearest neighbour gives the same
  * value, bit for bit. */
std::vector<double>
nearestNeighbourSquared (const std::uint32_t* simplices, std::size_t count, int dimension,
                         const std::vector<Point3>& positions);

/** \brief The median, over the vertices, of the distance to the nearest vertex sharing a simplex
  * with it, for \a count simplices of \a dimension (>= 1) given by their vertex ids (dimension + 1
  * each). On a Delaunay triangulation (or its edges) that is the median nearest-neighbour distance,
  * exactly: the nearest neighbour of a point is a Delaunay neighbour. All in double precision,
  * so it holds far from the origin. 0 when no vertex has a neighbour. */
double
medianNearestNeighbourDistance (const std::uint32_t* simplices, std::size_t count, int dimension,
                                const std::vector<Point3>& positions);

} // namespace pcl_wrap::detail

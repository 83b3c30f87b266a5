// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/simplicial_complex.h"

#include <pcl_wrap/compute_wrap.h>

#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief A point is apart from the others (an outlier) when it is more than this many median
  * spacings of the sample from every point but at most APART_CLUSTER - 1 others, and more than
  * this many times farther from the nearest of the rest than three quarters of its Delaunay
  * neighbours among them are from their own nearest points. An outlier beside a sampled surface
  * has nearly all its Delaunay neighbours on that surface; the vertices of a mesh, sparse on its
  * flat parts, are at most about ten median spacings apart, with half their neighbours as sparse,
  * and a part of a sample much sparser than the rest has neighbours as sparse. */
constexpr double APART_SPACINGS = 16.0;

/** \brief Up to this many outliers close together are apart: three points bound no solid, so a
  * closed surface through them is a web or a spike; four can be a small object of their own. */
constexpr std::uint8_t APART_CLUSTER = 3;

/** \brief Per vertex of Del S, 1 for a point apart from all others (APART_SPACINGS): no surface
  * that the points show passes through it, so the default surface leaves it off, where a closed
  * surface through it would be a spike. A few outliers close together are apart too, where most
  * of their neighbours are points of a much denser sample. Delaunay edges hold every point's
  * nearest neighbour. Empty where no point is apart (always below five points). */
std::vector<std::uint8_t>
pointsApart (const SimplicialComplex& complex, const std::vector<Point3>& positions);

} // namespace pcl_wrap::detail

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
  * spacings of the sample from every point but at most APART_CLUSTER - 1 others (its group), and
  * the group's nearest point of an object (a group of more than APART_CLUSTER points) is more than
  * this many times farther from it than three quarters of the group's Delaunay neighbours outside
  * (but those apart themselves) are from their own nearest points, those being points of an
  * object. An outlier beside a sampled surface has nearly all its Delaunay neighbours on that
  * surface; the vertices of a mesh, sparse on its flat parts, are at most about ten median
  * spacings apart, with half their neighbours as sparse, and a part of a sample much sparser than
  * the rest has neighbours as sparse. */
constexpr double APART_SPACINGS = 16.0;

/** \brief Up to this many outliers close together are apart: fewer points than FRAGMENT_VERTICES
  * (solid_join.h) show no object of their own, and a closed surface through them, tied to the
  * rest, is a spike. */
constexpr std::uint8_t APART_CLUSTER = 31;

/** \brief The points of a sample in groups, tied by Delaunay edges no longer than APART_SPACINGS
  * median spacings of the sample: every sample of one surface is one group; separate objects, far
  * apart at the scale of the whole sample, and outliers are groups of their own. */
struct SampleGroups
{
  std::vector<std::uint32_t> group; ///< per vertex: its group, named by one of its vertices
  std::vector<std::uint32_t> size;  ///< per vertex: the points of the group it names (0: none)
  std::vector<double> nearest;      ///< per vertex: the distance to its nearest neighbour
  std::size_t count = 0;            ///< the number of groups
};

/** \brief The groups of the points of Del S (empty below five points). Delaunay edges hold every
  * point's nearest neighbour. */
SampleGroups
sampleGroups (const SimplicialComplex& complex, const std::vector<Point3>& positions);

/** \brief Per vertex of Del S, 1 for a point apart from all others (APART_SPACINGS): no surface
  * that the points show passes through it, so the default surface leaves it off, where a closed
  * surface through it would be a spike. A few outliers close together are apart too, as a group,
  * where most of the group's neighbours are points of a much denser sample (a point inside the
  * group's hull may have no neighbour outside it). Empty where no point is apart (always below
  * five points).
  * \param[in] groups sampleGroups() */
std::vector<std::uint8_t>
pointsApart (const SimplicialComplex& complex, const std::vector<Point3>& positions, const SampleGroups& groups);

} // namespace pcl_wrap::detail

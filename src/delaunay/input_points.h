// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The set S of docs/design.md §1: finite, distinct weighted points, each remembering the
  * input index it came from. */
struct InputPoints
{
  std::vector<Point3> positions;
  std::vector<double> weights;
  std::vector<PointIndex> input_index; ///< per kept point

  std::vector<PointIndex> skipped;     ///< non-finite coordinate or weight
  /** \brief (dropped duplicate, the input index of the kept point at the same position). */
  std::vector<std::pair<PointIndex, PointIndex>> duplicates;
};

/** \brief The order that puts points at one position next to each other, the one that is kept
  * first: by position, then the largest weight, then the smallest index. For any record with
  * \c position, \c weight and \c index. */
template <class Record>
bool
keptBefore (const Record& a, const Record& b)
{
  if (a.position != b.position)
    return a.position < b.position;
  if (a.weight != b.weight)
    return a.weight > b.weight;
  return a.index < b.index;
}

/** \brief Drops non-finite points and keeps one of each set of points at the same position:
  * the one with the largest weight, ties broken by the smallest input index.
  * \param[in] weights empty (all zero) or one per point */
InputPoints
selectInputPoints (const std::vector<Point3>& points, const std::vector<double>& weights);

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_partition.h"

#include "tile_reach.h"

#include <algorithm>

namespace pcl_wrap::mpi
{

TilePartition::TilePartition (std::vector<Point3> sample, int tiles)
{
  build (sample, 0, sample.size (), 0, static_cast<std::uint32_t> (std::max (tiles, 1)));
}

std::uint32_t
TilePartition::build (std::vector<Point3>& sample, std::size_t begin, std::size_t end, std::uint32_t first,
                      std::uint32_t count)
{
  const auto at = static_cast<std::uint32_t> (cuts_.size ());
  cuts_.emplace_back ();
  if (count == 1)
  {
    cuts_[at].first = first;
    return at;
  }
  Box box;
  for (std::size_t i = begin; i < end; ++i)
    box.add (sample[i]);
  const int axis = box.longestAxis ();
  const std::uint32_t below = count / 2;
  const std::size_t middle = begin + (end - begin) * below / count;
  double cut = 0;
  if (middle < end)
  {
    std::nth_element (sample.begin () + begin, sample.begin () + middle, sample.begin () + end,
                      [&] (const Point3& a, const Point3& b) { return a[axis] < b[axis]; });
    cut = sample[middle][axis];
  }
  // Points below the cut go below: the sample's [begin, middle) may hold some at the cut's
  // coordinate; move those above, so that both halves are the points each side gets.
  const auto split =
      std::partition (sample.begin () + begin, sample.begin () + end, [&] (const Point3& p) { return p[axis] < cut; });
  const auto mid = static_cast<std::size_t> (split - sample.begin ());
  cuts_[at].axis = axis;
  cuts_[at].at = cut;
  const std::uint32_t b = build (sample, begin, mid, first, below);
  const std::uint32_t a = build (sample, mid, end, first + below, count - below);
  cuts_[at].below = b;
  cuts_[at].above = a;
  return at;
}

std::uint32_t
TilePartition::tileOf (const Point3& p) const
{
  std::uint32_t at = 0;
  while (cuts_[at].axis >= 0)
    at = p[cuts_[at].axis] < cuts_[at].at ? cuts_[at].below : cuts_[at].above;
  return cuts_[at].first;
}

} // namespace pcl_wrap::mpi

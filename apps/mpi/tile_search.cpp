// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_search.h"

#include <algorithm>

namespace pcl_wrap::mpi
{

TileSearch::TileSearch (std::vector<Point3> points) : points_ (std::move (points))
{
  if (!points_.empty ())
    build (0, static_cast<std::uint32_t> (points_.size ()));
}

std::uint32_t
TileSearch::build (std::uint32_t begin, std::uint32_t end)
{
  const auto at = static_cast<std::uint32_t> (nodes_.size ());
  nodes_.emplace_back ();
  Box box;
  for (std::uint32_t i = begin; i < end; ++i)
    box.add (points_[i]);
  nodes_[at].box = box;
  if (end - begin <= LEAF_POINTS)
  {
    nodes_[at].begin = begin;
    nodes_[at].end = end;
    return at;
  }
  const int axis = box.longestAxis ();
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element (points_.begin () + begin, points_.begin () + middle, points_.begin () + end,
                    [axis] (const Point3& a, const Point3& b) { return a[axis] < b[axis]; });
  const std::uint32_t below = build (begin, middle);
  const std::uint32_t above = build (middle, end);
  nodes_[at].below = below;
  nodes_[at].above = above;
  return at;
}

bool
TileSearch::anyMayBeIn (const TileReach& reach) const
{
  if (nodes_.empty ())
    return false;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty ())
  {
    const Node& node = nodes_[stack.back ()];
    stack.pop_back ();
    if (!reach.mayMeet (node.box))
      continue;
    if (node.below == 0)
    {
      for (std::uint32_t i = node.begin; i < node.end; ++i)
      {
        Box point;
        point.add (points_[i]);
        if (reach.mayMeet (point))
          return true;
      }
      continue;
    }
    stack.push_back (node.below);
    stack.push_back (node.above);
  }
  return false;
}

} // namespace pcl_wrap::mpi

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "tile_reach.h"

#include <pcl_wrap/compute_wrap.h>

#include <cstdint>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief A tile's own points in a k-d tree of boxes, to answer whether a tetrahedron of another
  * tile may reach one of them. */
class TileSearch
{
public:
  explicit TileSearch (std::vector<Point3> points);

  /** \brief Whether some point may be in \a reach: never false when one is (TileReach::mayMeet
    * on the tree's boxes, then on the points themselves). */
  bool anyMayBeIn (const TileReach& reach) const;

private:
  struct Node
  {
    Box box;
    std::uint32_t begin = 0, end = 0;   ///< points_[begin, end) when a leaf
    std::uint32_t below = 0, above = 0; ///< children, 0 for a leaf
  };
  std::uint32_t build (std::uint32_t begin, std::uint32_t end);

  static constexpr std::uint32_t LEAF_POINTS = 16;
  std::vector<Point3> points_;
  std::vector<Node> nodes_;
};

} // namespace pcl_wrap::mpi

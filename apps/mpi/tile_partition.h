// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "tile_reach.h"

#include <pcl_wrap/compute_wrap.h>

#include <cstdint>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief The points split into \a tiles tiles of nearly equal counts by recursive bisection: each
  * cut halves a set of tiles along the longest side of its points' bounding box, at the point
  * whose rank gives each side its share. Tiles may touch or overlap at a cut where coordinates
  * repeat; nothing relies on them being apart. The result depends on the points alone. */
struct TilePartition
{
  std::vector<std::uint32_t> tile_of_point;
  std::vector<Box> boxes; ///< per tile, the bounding box of its points (empty for none)
};

TilePartition
partitionIntoTiles (const std::vector<Point3>& points, int tiles);

} // namespace pcl_wrap::mpi

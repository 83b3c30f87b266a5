// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <cstdint>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief Space cut into tiles by recursive bisection: each cut halves a set of tiles along the
  * longest side of its sample points' bounding box, at the sample point whose rank gives each
  * side its share. A point goes below a cut when its coordinate is smaller than the cut's, so
  * points at the same position share a tile. Built from a sample that every rank holds alike,
  * the tiles are the same on every rank. */
class TilePartition
{
public:
  TilePartition (std::vector<Point3> sample, int tiles);

  std::uint32_t tileOf (const Point3& p) const;

private:
  struct Cut
  {
    int axis = -1; ///< -1: a leaf, tile `first`
    double at = 0;
    std::uint32_t below = 0, above = 0; ///< child cuts
    std::uint32_t first = 0;
  };
  std::uint32_t build (std::vector<Point3>& sample, std::size_t begin, std::size_t end, std::uint32_t first,
                       std::uint32_t count);

  std::vector<Cut> cuts_;
};

} // namespace pcl_wrap::mpi

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_partition.h"

#include <algorithm>
#include <numeric>

namespace pcl_wrap::mpi
{
namespace
{

/** Gives tiles first .. first + count - 1 the points ids[begin, end). */
void
bisect (const std::vector<Point3>& points, std::vector<std::uint32_t>& ids, std::size_t begin, std::size_t end,
        std::uint32_t first, std::uint32_t count, TilePartition& out)
{
  if (count == 1)
  {
    for (std::size_t i = begin; i < end; ++i)
      out.tile_of_point[ids[i]] = first;
    return;
  }
  Box box;
  for (std::size_t i = begin; i < end; ++i)
    box.add (points[ids[i]]);
  int axis = 0;
  if (!box.empty)
    for (int c = 1; c < 3; ++c)
      if (box.hi[c] - box.lo[c] > box.hi[axis] - box.lo[axis])
        axis = c;
  const std::uint32_t left = count / 2;
  const std::size_t middle = begin + (end - begin) * left / count;
  // Ties by index, so that the cut is the same whatever the order of ids.
  std::nth_element (ids.begin () + begin, ids.begin () + middle, ids.begin () + end,
                    [&] (std::uint32_t a, std::uint32_t b) {
                      return points[a][axis] != points[b][axis] ? points[a][axis] < points[b][axis] : a < b;
                    });
  bisect (points, ids, begin, middle, first, left, out);
  bisect (points, ids, middle, end, first + left, count - left, out);
}

} // namespace

TilePartition
partitionIntoTiles (const std::vector<Point3>& points, int tiles)
{
  TilePartition out;
  out.tile_of_point.assign (points.size (), 0);
  out.boxes.assign (static_cast<std::size_t> (tiles), Box ());
  std::vector<std::uint32_t> ids (points.size ());
  std::iota (ids.begin (), ids.end (), 0u);
  bisect (points, ids, 0, ids.size (), 0, static_cast<std::uint32_t> (tiles), out);
  for (std::size_t i = 0; i < points.size (); ++i)
    out.boxes[out.tile_of_point[i]].add (points[i]);
  return out;
}

} // namespace pcl_wrap::mpi

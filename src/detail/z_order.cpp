// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "z_order.h"

#include "parallel_for_each.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

/** The 21 low bits of \a x spread to every third bit. */
std::uint64_t
spread (std::uint64_t x)
{
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

} // namespace

std::vector<std::uint32_t>
zOrder (const std::vector<Point3>& points)
{
  Point3 low, high;
  low.fill (std::numeric_limits<double>::infinity ());
  high.fill (-std::numeric_limits<double>::infinity ());
  for (const Point3& p : points)
    for (int c = 0; c < 3; ++c)
      low[c] = std::min (low[c], p[c]), high[c] = std::max (high[c], p[c]);
  // Cells per unit length on each axis; the extent may overflow to infinity for huge spreads,
  // and then the scale is 0 and that axis orders nothing (any order is correct, only slower).
  constexpr double CELLS = 0x1p21 - 1;
  double scale[3];
  for (int c = 0; c < 3; ++c)
  {
    const double extent = high[c] - low[c];
    scale[c] = extent > 0 && extent < std::numeric_limits<double>::infinity () ? CELLS / extent : 0.0;
  }

  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys (points.size ());
  parallelForEach (points.size (), [&] (std::size_t i) {
    std::uint64_t key = 0;
    for (int c = 0; c < 3; ++c)
    {
      const double cell = std::clamp ((points[i][c] - low[c]) * scale[c], 0.0, CELLS);
      key |= spread (static_cast<std::uint64_t> (cell)) << c;
    }
    keys[i] = {key, static_cast<std::uint32_t> (i)};
  });
  tbb::parallel_sort (keys.begin (), keys.end ());
  std::vector<std::uint32_t> order (points.size ());
  parallelForEach (points.size (), [&] (std::size_t i) { order[i] = keys[i].second; });
  return order;
}

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "delaunay/z_order.h"

#include "util/parallel_for_each.h"

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
  // An axis whose extent overflows to infinity orders nothing (any order is correct, only
  // slower); otherwise a point's place along it, (p - low) / extent, lies in [0, 1], as the
  // rounded difference never exceeds the rounded extent.
  constexpr double CELLS = 0x1p21 - 1;
  double extent[3];
  for (int c = 0; c < 3; ++c)
    extent[c] = high[c] - low[c];
  const auto cell = [&] (double x, int c) -> std::uint64_t {
    if (!(extent[c] > 0 && extent[c] < std::numeric_limits<double>::infinity ()))
      return 0;
    return static_cast<std::uint64_t> (std::clamp ((x - low[c]) / extent[c], 0.0, 1.0) * CELLS);
  };

  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys (points.size ());
  parallelForEach (points.size (), [&] (std::size_t i) {
    std::uint64_t key = 0;
    for (int c = 0; c < 3; ++c)
      key |= spread (cell (points[i][c], c)) << c;
    keys[i] = {key, static_cast<std::uint32_t> (i)};
  });
  tbb::parallel_sort (keys.begin (), keys.end ());
  std::vector<std::uint32_t> order (points.size ());
  parallelForEach (points.size (), [&] (std::size_t i) { order[i] = keys[i].second; });
  return order;
}

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// libFuzzer: arbitrary bytes as coordinates (NaN, +-Inf, denormals, huge values, duplicates)
// into the whole construction. Besides not crashing, the output must be well formed.
#include <pcl_wrap/compute_wrap.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>
#include <vector>

namespace
{

void
require (bool condition)
{
  if (!condition)
    std::abort ();
}

} // namespace

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  // The first byte picks how to read the rest: doubles, or floats (as PCL clouds hold them). At
  // most 48 points: extreme magnitudes send every predicate to exact arithmetic, which is slow.
  if (size < 1)
    return 0;
  const bool floats = data[0] & 1;
  ++data, --size;
  const std::size_t width = floats ? sizeof (float) : sizeof (double);
  std::vector<pcl_wrap::Point3> points (std::min<std::size_t> (size / (3 * width), 48));
  for (std::size_t i = 0; i < points.size (); ++i)
    for (int a = 0; a < 3; ++a)
    {
      const std::uint8_t* at = data + (3 * i + a) * width;
      if (floats)
      {
        float f;
        std::memcpy (&f, at, sizeof (f));
        points[i][a] = f;
      }
      else
        std::memcpy (&points[i][a], at, sizeof (double));
    }

  const pcl_wrap::WrapResult r = pcl_wrap::computeWrap (points);
  const std::set<pcl_wrap::PointIndex> skipped (r.skipped.begin (), r.skipped.end ());
  // Index n + k is a copy of point copies[k] (pinches split by the surface stage).
  const auto original = [&] (pcl_wrap::PointIndex v) {
    return v < points.size () ? v : r.copies.at (v - points.size ());
  };
  for (const auto& t : r.surface.triangles)
    for (auto v : t)
      require (v < points.size () + r.copies.size () && !skipped.count (original (v)));
  require (r.statistics.points_used + r.statistics.points_skipped + r.statistics.points_duplicate +
               r.statistics.points_hidden == points.size ());
  require (r.statistics.x_simplices[0] == r.statistics.points_used); // every point is a vertex of X (P4)
  return 0;
}

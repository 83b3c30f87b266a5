// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "bench_points.h"

#include "point_file.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace pcl_wrap::bench
{

std::vector<Point3>
makePoints (const std::string& shape, std::size_t n, unsigned seed)
{
  if (shape != "sphere" && shape != "cube" && shape != "torus" && shape != "terrain" && shape != "rough_terrain" &&
      shape != "half_sphere")
    return pcl_wrap::apps::readPoints (shape);
  const double spacing = 2.0 / std::sqrt (double (std::max<std::size_t> (n, 1))); // of a terrain
  std::mt19937_64 random (seed);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u (-1.0, 1.0), angle (0.0, 2.0 * M_PI);
  std::vector<Point3> p (n);
  for (auto& q : p)
    if (shape == "cube")
      q = {u (random), u (random), u (random)};
    else if (shape == "terrain")
    {
      const double x = u (random), y = u (random);
      q = {x, y, 0.2 * std::sin (3 * x) * std::cos (2 * y)};
    }
    else if (shape == "rough_terrain")
    {
      const double x = u (random), y = u (random);
      q = {x, y,
           0.2 * std::sin (3 * x) * std::cos (2 * y) + 0.02 * std::sin (40 * x) * std::cos (37 * y) +
               0.2 * spacing * g (random)};
    }
    else if (shape == "half_sphere")
    {
      // Radial noise of 0.4 times the spacing at every size (1e-3 at 1M points): the same kind of
      // layer, where a fixed noise would make the largest clouds a noisy shell of some thickness.
      const double noise = 0.4 * std::sqrt (2.0 * M_PI / double (std::max<std::size_t> (n, 1)));
      const double x = g (random), y = g (random), z = std::fabs (g (random));
      const double r = (1.0 + noise * u (random)) / std::sqrt (x * x + y * y + z * z);
      q = {x * r, y * r, z * r};
    }
    else if (shape == "torus")
    {
      const double a = angle (random), b = angle (random);
      q = {(1.0 + 0.4 * std::cos (b)) * std::cos (a), (1.0 + 0.4 * std::cos (b)) * std::sin (a), 0.4 * std::sin (b)};
    }
    else
    {
      const double x = g (random), y = g (random), z = g (random);
      const double r = (1.0 + 1e-3 * u (random)) / std::sqrt (x * x + y * y + z * z);
      q = {x * r, y * r, z * r};
    }
  return p;
}

double
boundingBoxDiagonal (const std::vector<Point3>& points)
{
  if (points.empty ())
    return 0.0;
  Point3 lo = points.front (), hi = points.front ();
  for (const auto& q : points)
    for (int i = 0; i < 3; ++i)
      lo[i] = std::min (lo[i], q[i]), hi[i] = std::max (hi[i], q[i]);
  return std::sqrt ((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                    (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

} // namespace pcl_wrap::bench

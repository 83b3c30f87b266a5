// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// Seeded point samples for the tests: the same seed gives the same points everywhere.
#include <pcl_wrap/compute_wrap.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace pcl_wrap::test
{

inline std::vector<Point3>
cubeSample (std::size_t n, unsigned seed)
{
  std::mt19937_64 random (seed);
  std::uniform_real_distribution<double> u (-1.0, 1.0);
  std::vector<Point3> p (n);
  for (auto& q : p)
    q = {u (random), u (random), u (random)};
  return p;
}

/** Uniform on the unit sphere, each point moved radially by up to \a noise. */
inline std::vector<Point3>
sphereSample (std::size_t n, unsigned seed, double noise = 1e-3)
{
  std::mt19937_64 random (seed);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u (-noise, noise);
  std::vector<Point3> p (n);
  for (auto& q : p)
  {
    double x = g (random), y = g (random), z = g (random);
    const double r = (1.0 + u (random)) / std::sqrt (x * x + y * y + z * z);
    q = {x * r, y * r, z * r};
  }
  return p;
}

/** Uniform on the unit sphere, each coordinate then moved by Gaussian noise of deviation \a sigma. */
inline std::vector<Point3>
noisySphereSample (std::size_t n, unsigned seed, double sigma)
{
  std::mt19937_64 random (seed);
  std::normal_distribution<double> g;
  std::vector<Point3> p (n);
  for (auto& q : p)
  {
    const double x = g (random), y = g (random), z = g (random), r = std::sqrt (x * x + y * y + z * z);
    q = {x / r + sigma * g (random), y / r + sigma * g (random), z / r + sigma * g (random)};
  }
  return p;
}

/** Uniform in angle on a torus with radii \a major > \a minor around the z-axis. */
inline std::vector<Point3>
torusSample (std::size_t n, unsigned seed, double major = 1.0, double minor = 0.4)
{
  std::mt19937_64 random (seed);
  std::uniform_real_distribution<double> angle (0.0, 2.0 * M_PI);
  std::vector<Point3> p (n);
  for (auto& q : p)
  {
    const double a = angle (random), b = angle (random);
    q = {(major + minor * std::cos (b)) * std::cos (a), (major + minor * std::cos (b)) * std::sin (a),
         minor * std::sin (b)};
  }
  return p;
}

/** A height field seen from above, z = 0.2 sin 3x cos 2y over [-1, 1]^2: a single layer, with no
  * inside behind it, that lies on its own convex hull where it bends upward. */
inline std::vector<Point3>
terrainSample (std::size_t n, unsigned seed)
{
  std::mt19937_64 random (seed);
  std::uniform_real_distribution<double> u (-1.0, 1.0);
  std::vector<Point3> p (n);
  for (auto& q : p)
  {
    const double x = u (random), y = u (random);
    q = {x, y, 0.2 * std::sin (3 * x) * std::cos (2 * y)};
  }
  return p;
}

/** terrainSample() moved across, in z, by Gaussian noise of \a sigma mean spacings (2 / sqrt n;
  * the median spacing is about half of it). */
inline std::vector<Point3>
noisyTerrainSample (std::size_t n, unsigned seed, double sigma)
{
  std::vector<Point3> p = terrainSample (n, seed);
  std::mt19937_64 random (seed + 5);
  std::normal_distribution<double> noise (0.0, sigma * 2.0 / std::sqrt (double (n)));
  for (auto& q : p)
    q[2] += noise (random);
  return p;
}

/** A surface of genus 2: two tori (radii 1 and 0.4, around z-axes through (-1.1, 0, 0) and
  * (1.1, 0, 0)) fused where they overlap, each torus's points inside the other's solid dropped.
  * The two tunnels' axes are x = -1.1 and x = 1.1. */
inline std::vector<Point3>
doubleTorusSample (std::size_t n, unsigned seed)
{
  constexpr double CENTRE = 1.1, MAJOR = 1.0, MINOR = 0.4;
  const auto insideSolid = [] (const Point3& q, double cx) {
    const double ring = std::hypot (q[0] - cx, q[1]) - MAJOR;
    return ring * ring + q[2] * q[2] < MINOR * MINOR;
  };
  std::vector<Point3> points;
  for (const double cx : {-CENTRE, CENTRE})
    for (Point3 q : torusSample (n / 2, seed + (cx > 0), MAJOR, MINOR))
    {
      q[0] += cx;
      if (!insideSolid (q, -cx))
        points.push_back (q);
    }
  return points;
}

/** Points (t, t^2, t^3) for sorted random t in [0, 1]: point i is the i-th along the curve. */
inline std::vector<Point3>
momentCurveSample (std::size_t n, unsigned seed)
{
  std::mt19937_64 random (seed);
  std::uniform_real_distribution<double> u (0.0, 1.0);
  std::vector<double> t (n);
  for (auto& s : t)
    s = u (random);
  std::sort (t.begin (), t.end ());
  std::vector<Point3> p (n);
  for (std::size_t i = 0; i < n; ++i)
    p[i] = {t[i], t[i] * t[i], t[i] * t[i] * t[i]};
  return p;
}

} // namespace pcl_wrap::test

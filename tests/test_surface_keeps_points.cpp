// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The default surface loses no point the paper's W has on it (docs/surface.md), and points that
// sample a volume give the volume's outer boundary, W's, with the points inside left inside.
#include "support/degenerate_samples.h"
#include "support/samplers.h"
#include "support/topology.h"
#include "support/wrap_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

/** \a n points in \a blobs Gaussian clusters of random centres and sizes. */
std::vector<Point3>
blobSample (std::size_t n, int blobs, unsigned seed)
{
  std::mt19937_64 random (seed);
  std::uniform_real_distribution<double> u (-1.0, 1.0), size (0.05, 0.4);
  std::normal_distribution<double> g;
  std::vector<Point3> centres (blobs);
  std::vector<double> sizes (blobs);
  for (int b = 0; b < blobs; ++b)
  {
    centres[b] = {u (random), u (random), u (random)};
    sizes[b] = size (random);
  }
  std::vector<Point3> p (n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const int b = static_cast<int> (i % blobs);
    p[i] = {centres[b][0] + sizes[b] * g (random), centres[b][1] + sizes[b] * g (random),
            centres[b][2] + sizes[b] * g (random)};
  }
  return p;
}

/** \a n points, Gaussian or uniform in a cube (cubeSample()): too few to show a shape. */
std::vector<Point3>
tinyCloud (std::size_t n, bool gaussian, unsigned seed)
{
  if (!gaussian)
    return cubeSample (n, seed);
  std::mt19937_64 random (seed);
  std::normal_distribution<double> g;
  std::vector<Point3> p (n);
  for (Point3& q : p)
    q = {g (random), g (random), g (random)};
  return p;
}

std::vector<NamedSample>
samples ()
{
  std::vector<NamedSample> s = degenerateFamilies ();
  for (unsigned seed = 1; seed <= 4; ++seed)
  {
    const std::string k = " " + std::to_string (seed);
    s.push_back ({"sphere" + k, sphereSample (400 * seed, seed, 0.0)});
    s.push_back ({"sphere, noise of about a spacing" + k, sphereSample (3000, seed, 0.02)});
    s.push_back ({"thick noisy shell (a volume)" + k, sphereSample (1500 * seed, seed, 0.2)});
    s.push_back ({"uniform cube (a volume)" + k, cubeSample (500 * seed, seed)});
    s.push_back ({"torus" + k, torusSample (1000 * seed, seed)});
    s.push_back ({"terrain" + k, terrainSample (600 * seed, seed)});
    s.push_back ({"gaussian blobs" + k, blobSample (300 * seed, 1 + static_cast<int> (seed), seed)});
  }
  s.push_back ({"grid 11^3", gridSample (11, 11, 11)});
  return s;
}

/** The default surface is what it promises: one oriented sheet for a single layer; else, where
  * the points span space, a closed, oriented 2-manifold. */
void
expectClosedOrOneSheet (const WrapResult& r)
{
  const std::vector<Triangle> triangles (r.surface.triangles.begin (), r.surface.triangles.end ());
  if (r.statistics.single_layer)
  {
    const OpenSurfaceReport s = describeOpenSurface (triangles);
    EXPECT_TRUE (s.manifold);
    EXPECT_TRUE (s.consistently_oriented);
  }
  else if (r.statistics.triangulation_dimension == 3)
  {
    const SurfaceReport s = describeSurface (triangles);
    EXPECT_TRUE (s.closed_manifold);
    EXPECT_TRUE (s.consistently_oriented);
  }
}

TEST (SurfaceKeepsPoints, NeverFewerPointsOnItThanOnThePapersW)
{
  for (const auto& [name, points] : samples ())
  {
    SCOPED_TRACE (name);
    const std::size_t on_w = pointsOnSurface (computeWrap (points, rawOutput ()), points.size ()).size ();
    const WrapResult r = computeWrap (points);
    EXPECT_GE (pointsOnSurface (r, points.size ()).size (), on_w);
    expectClosedOrOneSheet (r);
  }
}

/** Each of the \a n points given is on a triangle of \a r's output (itself or as a copy), as a
  * mesh shows it, or in exactly one of the lists that say where it went: off the surface,
  * skipped, hidden, a duplicate. */
void
expectEveryPointAccountedFor (const WrapResult& r, std::size_t n)
{
  std::vector<int> places (n, 0);
  for (PointIndex p : pointsOnSurface (r, n))
    ++places[p];
  for (const std::vector<PointIndex>* list : {&r.off_surface, &r.skipped, &r.hidden})
    for (PointIndex p : *list)
      ++places[p];
  for (const auto& d : r.duplicates)
    ++places[d.first];
  for (std::size_t p = 0; p < n; ++p)
    ASSERT_EQ (places[p], 1) << "point " << p << " is in " << places[p] << " places";
  EXPECT_TRUE (std::is_sorted (r.off_surface.begin (), r.off_surface.end ()));
  EXPECT_TRUE (std::includes (r.off_surface.begin (), r.off_surface.end (), r.apart.begin (), r.apart.end ()));
  EXPECT_EQ (r.statistics.points_off_surface, r.off_surface.size ());
}

TEST (SurfaceKeepsPoints, EveryPointIsOnTheSurfaceOrReportedOff)
{
  std::vector<NamedSample> clouds = samples ();
  // NaNs, duplicates and two far outliers around a sphere.
  std::vector<Point3> mixed = sphereSample (2000, 3, 0.0);
  mixed[10] = {std::numeric_limits<double>::quiet_NaN (), 0.0, 0.0};
  mixed.push_back (mixed[20]);
  mixed.push_back ({40.0, 0.0, 0.0});
  mixed.push_back ({0.0, -60.0, 0.0});
  clouds.push_back ({"sphere with a NaN, a duplicate and two outliers", mixed});
  WrapParameters closed, raw = rawOutput (), raw_manifold = rawOutput ();
  closed.output = Output::closed;
  raw_manifold.manifold = true;
  std::size_t off_default = 0, off_raw = 0;
  for (const auto& [name, points] : clouds)
    for (const WrapParameters& parameters : {WrapParameters{}, closed, raw, raw_manifold})
    {
      SCOPED_TRACE (name + ", output " + std::to_string (static_cast<int> (parameters.output)) +
                    (parameters.manifold ? ", manifold" : ""));
      const WrapResult r = computeWrap (points, parameters);
      expectEveryPointAccountedFor (r, points.size ());
      (parameters.output == Output::raw ? off_raw : off_default) += r.off_surface.size ();
      if (name == clouds.back ().name && parameters.output != Output::raw)
        EXPECT_EQ (r.apart, (std::vector<PointIndex>{2001, 2002})) << "the outliers, off the surface";
    }
  // The volumes leave points inside: the lists are not empty.
  EXPECT_GT (off_default, 0u);
  EXPECT_GT (off_raw, 0u);
  // Weights: a point whose power cell is empty is hidden, not off the surface.
  std::vector<Point3> weighted = sphereSample (800, 4, 0.0);
  weighted.push_back ({0.0, 0.0, 0.0});
  std::vector<double> weights (weighted.size (), 0.0);
  weights.back () = -10.0;
  const WrapResult r = computeWrap (weighted, weights);
  EXPECT_EQ (r.hidden, std::vector<PointIndex>{800});
  expectEveryPointAccountedFor (r, weighted.size ());
}

TEST (SurfaceKeepsPoints, TinyCloudsGiveAClosedManifoldThroughAllOfWsPoints)
{
  // A few scattered points lie inside their convex hull, and the solid is X's (a volume's). Where
  // the solid's surface would still leave more of W's points off than it has points that W has
  // not (a point that X holds by a fin, more than a tetrahedron from the surface), the output is
  // W itself, split as the raw output's manifold split does.
  constexpr unsigned CLOUDS = 300;
  unsigned took_w = 0;
  WrapParameters manifold = rawOutput ();
  manifold.manifold = true;
  for (unsigned seed = 1; seed <= CLOUDS; ++seed)
  {
    const std::vector<Point3> points = tinyCloud (5 + seed % 76, seed % 2 == 1, seed);
    SCOPED_TRACE (seed);
    const std::size_t on_w = pointsOnSurface (computeWrap (points, rawOutput ()), points.size ()).size ();
    const WrapResult r = computeWrap (points);
    EXPECT_GE (pointsOnSurface (r, points.size ()).size (), on_w);
    ASSERT_EQ (r.statistics.triangulation_dimension, 3);
    expectClosedOrOneSheet (r);
    if (r.statistics.surface_is_w)
    {
      ++took_w;
      EXPECT_EQ (r.surface.triangles, computeWrap (points, manifold).surface.triangles);
    }
  }
  // The labelled solid holds W's points nearly always: W, with its sheets doubled, is the rare
  // answer.
  EXPECT_LE (took_w, CLOUDS / 100);
  std::printf ("tiny clouds whose output is W, split: %u of %u\n", took_w, CLOUDS);
}

TEST (SurfaceKeepsPoints, AVolumeGivesItsOuterBoundary)
{
  // A grid's W is the cube's boundary: the labelling's solid has nothing to add, and the points
  // inside stay inside.
  for (int n : {12, 16})
  {
    SCOPED_TRACE (n);
    const std::vector<Point3> grid = gridSample (n, n, n);
    const WrapResult r = computeWrap (grid);
    const SurfaceReport s = describeSurface ({r.surface.triangles.begin (), r.surface.triangles.end ()});
    EXPECT_TRUE (s.closed_manifold);
    EXPECT_EQ (s.components, 1u);
    EXPECT_EQ (s.euler, 2);
    const std::set<PointIndex> on = pointsOnSurface (r, grid.size ());
    std::size_t on_boundary = 0;
    for (PointIndex v : on)
    {
      const auto& p = grid[v];
      on_boundary += p[0] == 0 || p[1] == 0 || p[2] == 0 || p[0] == n - 1 || p[1] == n - 1 || p[2] == n - 1;
    }
    EXPECT_EQ (on.size (), on_boundary) << "no point inside the cube on it";
    EXPECT_EQ (on_boundary, std::size_t (n * n * n - (n - 2) * (n - 2) * (n - 2))) << "every point on its boundary";
  }
  // Uniform points in a cube: one closed surface, the points inside off it.
  const std::vector<Point3> cube = cubeSample (4000, 5);
  const WrapResult r = computeWrap (cube);
  const SurfaceReport s = describeSurface ({r.surface.triangles.begin (), r.surface.triangles.end ()});
  EXPECT_EQ (s.components, 1u);
  EXPECT_LT (pointsOnSurface (r, cube.size ()).size () * 2, cube.size ());
}

TEST (SurfaceKeepsPoints, AThickShellGivesAnOuterSurfaceOfGenusZero)
{
  // Points scattered through a shell around the unit sphere (radial Gaussian noise of two to three
  // spacings) mostly sample a volume, whose solid is X's tetrahedra. Those can have a tunnel that
  // a sheet of X's triangles spans: the surface must not go round it. Four of these six clouds
  // have such a tunnel.
  std::size_t volumes = 0;
  for (unsigned seed = 1; seed <= 3; ++seed)
    for (double sigma : {0.03, 0.04})
    {
      SCOPED_TRACE ("seed " + std::to_string (seed) + ", sigma " + std::to_string (sigma));
      std::vector<Point3> shell = sphereSample (20000, seed, 0.0);
      std::mt19937_64 random (seed);
      std::normal_distribution<double> g (1.0, sigma);
      for (Point3& p : shell)
      {
        const double r = g (random);
        p = {p[0] * r, p[1] * r, p[2] * r};
      }
      const WrapResult r = computeWrap (shell);
      const SurfaceReport s = describeSurface ({r.surface.triangles.begin (), r.surface.triangles.end ()});
      EXPECT_TRUE (s.closed_manifold);
      EXPECT_EQ (s.components, 1u);
      EXPECT_EQ (s.euler, 2) << "genus 0";
      volumes += 3 * pointsOnSurface (r, shell.size ()).size () < 2 * shell.size ();
    }
  EXPECT_GE (volumes, 4u) << "most of them taken for a volume, a third of the points or more inside";
}

} // namespace
} // namespace pcl_wrap::test

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The default surface on degenerate input, and its independence of the order of the points and of
// the number of threads (docs/surface.md), as the raw output's are tested in test_degenerate.
#include "support/degenerate_samples.h"
#include "support/samplers.h"
#include "support/topology.h"
#include "support/wrap_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace pcl_wrap::test
{
namespace
{

using Corner = std::array<double, 3>;
using OrientedTriangle = std::array<Corner, 3>;

/** The surface's triangles by the coordinates of their corners (a copy of a point has the point's),
  * each turned to start at its least corner so that the orientation is kept: what the surface is,
  * whatever the indices. A flat input's W is a sheet, oriented one way or the other (docs/design.md
  * §8): its corners are sorted. */
std::multiset<OrientedTriangle>
geometryOf (const std::vector<Point3>& points, const WrapResult& r)
{
  const bool flat = r.statistics.triangulation_dimension < 3;
  const auto at = [&] (PointIndex i) { return points[i < points.size () ? i : r.copies.at (i - points.size ())]; };
  std::multiset<OrientedTriangle> out;
  for (const auto& t : r.surface.triangles)
  {
    OrientedTriangle c{at (t[0]), at (t[1]), at (t[2])};
    if (flat)
      std::sort (c.begin (), c.end ());
    else
      std::rotate (c.begin (), std::min_element (c.begin (), c.end ()), c.end ());
    out.insert (c);
  }
  return out;
}

std::vector<NamedSample>
families ()
{
  auto f = degenerateFamilies ();
  f.push_back ({"random cube", cubeSample (500, 8)});
  f.push_back ({"noisy sphere", sphereSample (500, 8, 0.01)});
  f.push_back ({"torus", torusSample (1500, 3)});
  f.push_back ({"terrain", terrainSample (800, 2)});
  return f;
}

TEST (SurfaceInvariance, EveryDegenerateFamilyGivesAnOrientedManifold)
{
  for (const auto& [name, points] : families ())
  {
    SCOPED_TRACE (name);
    const WrapResult r = computeWrap (points);
    if (r.statistics.triangulation_dimension < 3)
    {
      // Nothing to label: the paper's W, as the raw output has it.
      const WrapResult raw = computeWrap (points, rawOutput ());
      EXPECT_EQ (r.surface.triangles, raw.surface.triangles);
      EXPECT_EQ (r.surface.dangling_edges, raw.surface.dangling_edges);
      EXPECT_EQ (r.surface.isolated_vertices, raw.surface.isolated_vertices);
      continue;
    }
    EXPECT_GT (r.surface.triangles.size (), 0u);
    EXPECT_TRUE (r.surface.dangling_edges.empty ());
    EXPECT_TRUE (r.surface.isolated_vertices.empty ());
    const std::vector<Triangle> triangles (r.surface.triangles.begin (), r.surface.triangles.end ());
    if (r.statistics.single_layer) // one open sheet
    {
      const OpenSurfaceReport s = describeOpenSurface (triangles);
      EXPECT_TRUE (s.manifold);
      EXPECT_TRUE (s.consistently_oriented);
      EXPECT_TRUE (s.no_duplicate_triangles);
      continue;
    }
    const SurfaceReport s = describeSurface (triangles);
    EXPECT_TRUE (s.closed_manifold);
    EXPECT_TRUE (s.consistently_oriented);
  }
}

TEST (SurfaceInvariance, PointsOnACurveGiveTheCurve)
{
  // Nearly collinear: Del S has tetrahedra, all slivers; X, the paper's answer, is the polyline.
  std::mt19937 random (5);
  std::normal_distribution<double> noise (0.0, 1e-12);
  std::vector<Point3> points;
  for (int i = 0; i < 1000; ++i)
  {
    const double t = std::uniform_real_distribution<double> (0.0, 1.0) (random);
    points.push_back ({t, 2 * t + noise (random), 3 * t + noise (random)});
  }
  const WrapResult raw = computeWrap (points, rawOutput ());
  ASSERT_EQ (raw.statistics.triangulation_dimension, 3);
  ASSERT_EQ (raw.statistics.x_simplices[2], 0u);
  const WrapResult r = computeWrap (points);
  EXPECT_TRUE (r.surface.triangles.empty ());
  EXPECT_EQ (r.surface.dangling_edges, raw.surface.dangling_edges);
  EXPECT_EQ (r.surface.dangling_edges.size (), 999u);
  EXPECT_TRUE (r.copies.empty ());
  // With a far outlier beside it, X ties the outlier to the curve by a triangle: the curve stays
  // the curve, and the outlier is left off.
  points.push_back ({0, 5, 0});
  const WrapResult beside = computeWrap (points);
  EXPECT_TRUE (beside.surface.triangles.empty ());
  EXPECT_EQ (beside.surface.dangling_edges, raw.surface.dangling_edges);
  EXPECT_EQ (beside.apart, std::vector<PointIndex>{1000});
}

TEST (SurfaceInvariance, DoesNotDependOnTheOrderOfThePoints)
{
  for (const auto& [name, points] : families ())
  {
    SCOPED_TRACE (name);
    const auto reference = geometryOf (points, computeWrap (points));
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
      auto shuffled = points;
      std::shuffle (shuffled.begin (), shuffled.end (), std::mt19937 (seed));
      EXPECT_TRUE (geometryOf (shuffled, computeWrap (shuffled)) == reference) << "shuffle " << seed;
    }
  }
}

TEST (SurfaceInvariance, DoesNotChangeWithTheNumberOfThreads)
{
  // Large enough for the parallel insertion, the concurrent flood and the parallel passes of the
  // repair; with ties (a grid) and a single layer.
  for (const auto& [name, points] : std::vector<NamedSample>{{"noisy sphere", sphereSample (30000, 5, 0.01)},
                                                             {"grid", gridSample (24, 24, 24)},
                                                             {"terrain", terrainSample (20000, 3)}})
  {
    SCOPED_TRACE (name);
    WrapParameters parameters;
    parameters.num_threads = 1;
    const WrapResult one = computeWrap (points, parameters);
    for (unsigned threads : {2u, 0u})
    {
      parameters.num_threads = threads;
      const WrapResult r = computeWrap (points, parameters);
      EXPECT_EQ (r.surface.triangles, one.surface.triangles) << threads << " threads";
      EXPECT_EQ (r.copies, one.copies);
      EXPECT_EQ (r.statistics.tetrahedra_moved, one.statistics.tetrahedra_moved);
      EXPECT_EQ (r.statistics.single_layer, one.statistics.single_layer);
    }
  }
}

} // namespace
} // namespace pcl_wrap::test

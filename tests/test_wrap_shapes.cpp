// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// What Wrap returns on shapes whose answer is known (docs/design.md §5, the paper's Figures 1-4),
// and on inputs whose triangulation has dimension 3, 2, 1, 0 or none.
#include "support/samplers.h"
#include "support/topology.h"
#include "support/wrap_checks.h"

#include <pcl_wrap/compute_wrap.h>


#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

namespace pcl_wrap::test
{
namespace
{

std::vector<Triangle>
trianglesOf (const WrapResult& r)
{
  return {r.surface.triangles.begin (), r.surface.triangles.end ()};
}

double
signedVolume (const std::vector<Point3>& p, const std::vector<Triangle>& triangles)
{
  double v = 0.0;
  for (const auto& t : triangles)
  {
    const Point3 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
    v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return v / 6.0;
}

TEST (WrapShapes, NoisySphereGivesClosedGenusZeroManifoldThroughEveryPoint)
{
  for (std::size_t n : {200u, 2000u})
    for (unsigned seed = 1; seed <= 4; ++seed)
    {
      SCOPED_TRACE ("n " + std::to_string (n) + " seed " + std::to_string (seed));
      const auto points = sphereSample (n, seed, 1e-3);
      const WrapResult r = computeWrap (points, rawOutput ());
      const SurfaceReport s = describeSurface (trianglesOf (r));
      EXPECT_TRUE (s.closed_manifold);
      EXPECT_TRUE (s.consistently_oriented);
      EXPECT_EQ (s.components, 1u);
      EXPECT_EQ (s.euler, 2); // genus 0
      EXPECT_EQ (s.vertices, n);
      EXPECT_TRUE (r.surface.dangling_edges.empty ());
      EXPECT_TRUE (r.surface.isolated_vertices.empty ());
      EXPECT_GT (signedVolume (points, trianglesOf (r)), 0.0) << "normals must point out of the solid";
    }
}

TEST (WrapShapes, MomentCurveGivesPathThroughConsecutivePoints)
{
  for (unsigned seed = 1; seed <= 5; ++seed)
  {
    const auto points = momentCurveSample (25, seed);
    const WrapResult r = computeWrap (points, rawOutput ());
    EXPECT_TRUE (r.surface.triangles.empty ());
    EXPECT_TRUE (r.surface.isolated_vertices.empty ());
    std::set<std::array<PointIndex, 2>> edges (r.surface.dangling_edges.begin (), r.surface.dangling_edges.end ());
    std::set<std::array<PointIndex, 2>> path;
    for (PointIndex i = 0; i + 1 < points.size (); ++i)
      path.insert ({i, i + 1});
    EXPECT_EQ (edges, path) << "seed " << seed;
  }
}

/** A torus: W is closed (a sheet triangle, with no tetrahedron of X behind it, bounds the
  * outside on both its sides and so counts twice), the tunnel is sealed by X, and the seal makes
  * W touch itself along pinch edges. Samples this sparse also keep a few sheet triangles (fins
  * of centered triangles; the classification of these very samples is checked against the exact
  * reference in test_classification). */
TEST (WrapShapes, TorusIsClosedAndSealedWithPinchEdges)
{
  std::size_t pinched = 0;
  for (unsigned seed = 1; seed <= 4; ++seed)
  {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    const auto points = torusSample (200, seed);
    const WrapResult r = computeWrap (points, rawOutput ());
    EXPECT_TRUE (r.surface.dangling_edges.empty ());
    EXPECT_TRUE (r.surface.isolated_vertices.empty ());

    EXPECT_EQ (openEdgeOfW (r), "") << "W is open there";
    pinched += pinchEdges (r) > 0;

    // Sealed: X (a tetrahedron, or a sheet of zero thickness) spans the tunnel: it meets the
    // tunnel's axis within the torus's height.
    EXPECT_TRUE (xMeetsSegment (r, points, {0, 0, -0.4}, {0, 0, 0.4})) << "the tunnel should be sealed by X";
  }
  EXPECT_GT (pinched, 0u) << "the sealed torus should touch itself along pinch edges";
}

TEST (WrapShapes, NoPointsGiveAnEmptyResult)
{
  const WrapResult r = computeWrap ({}, rawOutput ());
  EXPECT_EQ (r.statistics.triangulation_dimension, -1);
  EXPECT_TRUE (r.surface.triangles.empty () && r.surface.dangling_edges.empty () &&
               r.surface.isolated_vertices.empty ());
}

TEST (WrapShapes, OnePointIsAnIsolatedVertex)
{
  const WrapResult r = computeWrap ({{1, 2, 3}}, rawOutput ());
  EXPECT_EQ (r.statistics.triangulation_dimension, 0);
  EXPECT_EQ (r.surface.isolated_vertices, std::vector<PointIndex> ({0}));
}

TEST (WrapShapes, TwoPointsAreAnEdge)
{
  const WrapResult r = computeWrap ({{0, 0, 0}, {1, 1, 1}}, rawOutput ());
  EXPECT_EQ (r.statistics.triangulation_dimension, 1);
  ASSERT_EQ (r.surface.dangling_edges.size (), 1u);
  EXPECT_EQ (r.surface.dangling_edges[0], (std::array<PointIndex, 2>{0, 1}));
}

TEST (WrapShapes, AcuteTriangleStaysObtuseTriangleCollapsesToTwoEdges)
{
  const WrapResult acute = computeWrap ({{0, 0, 0}, {1, 0, 0}, {0.4, 0.9, 0}}, rawOutput ());
  EXPECT_EQ (acute.statistics.triangulation_dimension, 2);
  EXPECT_EQ (acute.surface.triangles.size (), 1u);
  EXPECT_TRUE (acute.surface.dangling_edges.empty ());

  // Obtuse at point 2: the long edge 0-1 is attached, so the triangle collapses through it.
  const WrapResult obtuse = computeWrap ({{0, 0, 0}, {1, 0, 0}, {0.5, 0.1, 0}}, rawOutput ());
  EXPECT_TRUE (obtuse.surface.triangles.empty ());
  std::set<std::array<PointIndex, 2>> edges (obtuse.surface.dangling_edges.begin (),
                                             obtuse.surface.dangling_edges.end ());
  EXPECT_EQ (edges, (std::set<std::array<PointIndex, 2>>{{0, 2}, {1, 2}}));
}

TEST (WrapShapes, CollinearPointsGiveThePathInOrderAlongTheLine)
{
  const WrapResult r = computeWrap ({{0, 0, 0}, {3, 3, 3}, {1, 1, 1}, {2, 2, 2}, {0.5, 0.5, 0.5}}, rawOutput ());
  EXPECT_EQ (r.statistics.triangulation_dimension, 1);
  std::set<std::array<PointIndex, 2>> edges (r.surface.dangling_edges.begin (), r.surface.dangling_edges.end ());
  EXPECT_EQ (edges, (std::set<std::array<PointIndex, 2>>{{0, 4}, {2, 4}, {2, 3}, {1, 3}}));
}

TEST (WrapShapes, CoplanarPointsGiveAContractiblePatch)
{
  // Dyadic coordinates on a tilted plane: z = x/4 - y/2 is computed exactly.
  std::mt19937 random (5);
  std::uniform_int_distribution<int> u (-4096, 4096);
  std::vector<Point3> points (300);
  for (auto& p : points)
  {
    p[0] = u (random) / 64.0;
    p[1] = u (random) / 64.0;
    p[2] = 0.25 * p[0] - 0.5 * p[1];
  }
  const WrapResult r = computeWrap (points, rawOutput ());
  ASSERT_EQ (r.statistics.triangulation_dimension, 2);
  const auto x = tuplesOfX (r);
  const Homology h = homology (x);
  EXPECT_EQ (h.components, 1u);
  EXPECT_EQ (h.euler, 1);
  EXPECT_EQ (h.betti1, 0u);
  EXPECT_EQ (r.statistics.x_simplices[2], r.surface.triangles.size ()); // every triangle is a sheet
  EXPECT_TRUE (describeSurface (trianglesOf (r)).consistently_oriented);
}

TEST (WrapShapes, ExactlyCoplanarGridIsTwoDimensional)
{
  std::vector<Point3> grid;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j)
      grid.push_back ({double (i), double (j), 0.0});
  const WrapResult r = computeWrap (grid, rawOutput ());
  EXPECT_EQ (r.statistics.triangulation_dimension, 2);
  EXPECT_EQ (r.statistics.x_simplices[0], grid.size ());
  const auto x = tuplesOfX (r);
  EXPECT_EQ (homology (x).euler, 1);
  EXPECT_EQ (homology (x).betti1, 0u);
}

TEST (WrapShapes, NonFiniteAndDuplicatePointsAreReportedAndNeverUsed)
{
  auto points = sphereSample (300, 3, 1e-3);
  const double nan = std::numeric_limits<double>::quiet_NaN ();
  const double inf = std::numeric_limits<double>::infinity ();
  points[10] = {nan, 0, 0};
  points[20] = {0, inf, 0};
  points.push_back (points[5]);  // 300: duplicate of 5
  points.push_back (points[7]);  // 301: duplicate of 7
  const WrapResult r = computeWrap (points, rawOutput ());
  EXPECT_EQ (r.skipped, (std::vector<PointIndex>{10, 20}));
  ASSERT_EQ (r.duplicates.size (), 2u);
  EXPECT_EQ (r.duplicates[0], (std::pair<PointIndex, PointIndex>{300, 5}));
  EXPECT_EQ (r.duplicates[1], (std::pair<PointIndex, PointIndex>{301, 7}));
  EXPECT_EQ (r.statistics.points_used, 298u);
  std::set<PointIndex> used;
  for (const auto& t : r.surface.triangles)
    used.insert (t.begin (), t.end ());
  for (PointIndex bad : {10u, 20u, 300u, 301u})
    EXPECT_FALSE (used.count (bad));
  EXPECT_EQ (used.size (), 298u);
  EXPECT_TRUE (describeSurface (trianglesOf (r)).closed_manifold);
}

TEST (WrapShapes, AllPointsNonFiniteGiveAnEmptyResult)
{
  const double nan = std::numeric_limits<double>::quiet_NaN ();
  const WrapResult r = computeWrap ({{nan, nan, nan}, {nan, 0, 0}}, rawOutput ());
  EXPECT_EQ (r.statistics.points_skipped, 2u);
  EXPECT_EQ (r.statistics.triangulation_dimension, -1);
}

} // namespace
} // namespace pcl_wrap::test

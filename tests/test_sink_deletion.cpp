// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// Sink deletion through the public API: thresholds as a squared radius, relative to the
// spacing, or a number of sinks; front and global modes; what the statistics report.
#include "support/samplers.h"
#include "support/topology.h"
#include "support/wrap_checks.h"

#include <pcl_wrap/compute_wrap.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace pcl_wrap::test
{
namespace
{

TEST (SinkDeletion, FrontModeOpensTheTorusTunnel)
{
  const auto points = torusSample (1000, 2);
  WrapParameters parameters = rawOutput ();
  parameters.threshold = Threshold::size (0.2); // between the tube's sinks (0.4^2) and the hole's (0.6^2)
  const WrapResult r = computeWrap (points, parameters);
  const SurfaceReport s = describeSurface ({r.surface.triangles.begin (), r.surface.triangles.end ()});
  EXPECT_TRUE (s.closed_manifold);
  EXPECT_EQ (s.euler, 0);
  EXPECT_EQ (s.vertices, points.size ());
  EXPECT_GE (r.statistics.sinks_deleted, 1u);
  EXPECT_EQ (r.statistics.sinks_not_principal, 0u);
  ASSERT_FALSE (r.statistics.largest_sinks.empty ());
  EXPECT_NEAR (r.statistics.largest_sinks[0], 0.36, 0.01) << "the hole's empty sphere";
  EXPECT_GT (r.statistics.spacing, 0.0);

  // Without a threshold: the basic wrap, which seals the tunnel.
  const WrapResult basic = computeWrap (points, rawOutput ());
  EXPECT_EQ (basic.statistics.sinks_deleted, 0u);
  EXPECT_TRUE (std::isinf (basic.statistics.delta));
  EXPECT_EQ (homology (tuplesOfX (basic)).betti1, 0u);
}

TEST (SinkDeletion, OneThresholdAtATime)
{
  const auto points = torusSample (1000, 2);
  WrapParameters parameters = rawOutput ();
  EXPECT_FALSE (parameters.threshold.deletes ()) << "the basic wrap by default";
  parameters.threshold = Threshold::relativeRadius (4);
  const WrapResult relative = computeWrap (points, parameters);
  EXPECT_GT (relative.statistics.sinks_deleted, 0u);
  parameters.threshold = Threshold::size (std::numeric_limits<double>::infinity ()); // replaces it
  EXPECT_FALSE (parameters.threshold.deletes ());
  EXPECT_EQ (computeWrap (points, parameters).surface.triangles, computeWrap (points, rawOutput ()).surface.triangles);
  for (const Threshold bad : {Threshold::relativeRadius (0), Threshold::relativeRadius (-1), Threshold::largest (0),
                              Threshold::size (std::numeric_limits<double>::quiet_NaN ())})
  {
    parameters.threshold = bad;
    EXPECT_THROW (computeWrap (points, parameters), std::invalid_argument);
  }
}

TEST (SinkDeletion, SpacingIsTheMedianNearestNeighbourDistance)
{
  // Distinct finite points, jittered; a duplicate and a NaN point are not points of their own.
  std::mt19937 random (5);
  std::uniform_real_distribution<double> u (0.0, 1.0);
  std::vector<Point3> points;
  for (int i = 0; i < 400; ++i)
    points.push_back ({u (random), u (random), 0.3 * u (random)});
  std::vector<double> nearest;
  for (const Point3& p : points)
  {
    double best = std::numeric_limits<double>::infinity ();
    for (const Point3& q : points)
      if (&p != &q)
        best = std::min (best, std::hypot (p[0] - q[0], p[1] - q[1], p[2] - q[2]));
    nearest.push_back (best);
  }
  std::nth_element (nearest.begin (), nearest.begin () + nearest.size () / 2, nearest.end ());
  points.push_back (points[7]);
  points.push_back ({std::numeric_limits<double>::quiet_NaN (), 0, 0});
  EXPECT_DOUBLE_EQ (medianSpacing (points), nearest[nearest.size () / 2]);

  WrapParameters relative;
  relative.threshold = Threshold::relativeRadius (4);
  EXPECT_DOUBLE_EQ (computeWrap (points, relative).statistics.spacing, medianSpacing (points));
}

TEST (SinkDeletion, SpacingHoldsFarFromTheOrigin)
{
  // A grid of step 0.01 at survey coordinates, where single precision cannot tell the points apart.
  std::vector<Point3> points;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      for (int k = 0; k < 3; ++k)
        points.push_back ({4.5e5 + 0.01 * i, 5.2e6 + 0.01 * j, 300 + 0.01 * k});
  EXPECT_NEAR (medianSpacing (points), 0.01, 1e-8);
  WrapParameters relative;
  relative.threshold = Threshold::relativeRadius (4);
  EXPECT_NEAR (computeWrap (points, relative).statistics.spacing, 0.01, 1e-8);
}

TEST (SinkDeletion, GlobalModeByCountOrThresholdAndTheRelativeRadius)
{
  const auto points = torusSample (1000, 2);
  WrapParameters three = rawOutput ();
  three.threshold = Threshold::largest (3);
  const WrapResult r = computeWrap (points, three);
  EXPECT_EQ (r.statistics.sinks_deleted + r.statistics.sinks_not_principal, 3u);
  const Homology h = homology (tuplesOfX (r));
  EXPECT_EQ (h.components, 1u);
  EXPECT_EQ (h.betti1, 1u) << "a solid torus";

  WrapParameters relative = rawOutput ();
  relative.deletion = SinkDeletion::global;
  relative.threshold = Threshold::relativeRadius (4);
  const WrapResult g = computeWrap (points, relative);
  EXPECT_DOUBLE_EQ (g.statistics.delta, std::pow (4 * g.statistics.spacing, 2));
  EXPECT_GT (g.statistics.sinks_deleted, r.statistics.sinks_deleted);
  EXPECT_EQ (g.statistics.sinks_not_principal, 0u);
  // After deletions X is no longer contractible, but still a complex whose boundary is W.
  for (const WrapResult* result : {&r, &g})
  {
    EXPECT_TRUE (closedUnderFaces (tuplesOfX (*result)));
    EXPECT_EQ (closureOfW (result->surface), boundaryByLinks (*result));
  }
}

} // namespace
} // namespace pcl_wrap::test

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

#include <cmath>

namespace pcl_wrap::test
{
namespace
{

TEST (SinkDeletion, FrontModeOpensTheTorusTunnel)
{
  const auto points = torusSample (1000, 2);
  WrapParameters parameters = rawOutput ();
  parameters.delta = 0.2; // between the tube's sinks (0.4^2) and the hole's (0.6^2)
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

TEST (SinkDeletion, GlobalModeByCountOrThresholdAndTheRelativeRadius)
{
  const auto points = torusSample (1000, 2);
  WrapParameters three = rawOutput ();
  three.sinks = 3;
  const WrapResult r = computeWrap (points, three);
  EXPECT_EQ (r.statistics.sinks_deleted + r.statistics.sinks_not_principal, 3u);
  const Homology h = homology (tuplesOfX (r));
  EXPECT_EQ (h.components, 1u);
  EXPECT_EQ (h.betti1, 1u) << "a solid torus";

  WrapParameters relative = rawOutput ();
  relative.deletion = SinkDeletion::global;
  relative.radius_rel = 4;
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

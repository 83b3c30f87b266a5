// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// Real data from Debian's libcgal-demo: the Stanford bunny (vertices of a closed scan), the
// kitten scan and the fandisk CAD model (full of exact ties the perturbation decides).
#include "support/front_checks.h"
#include "support/pipeline.h"
#include "support/topology.h"
#include "support/wrap_checks.h"

#include "point_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace pcl_wrap::test
{
namespace
{

std::vector<Point3>
load (const std::string& name)
{
  return apps::readPoints (std::string (PCL_WRAP_DATA_DIR) + "/" + name);
}

TEST (RealData, BunnyGivesClosedGenusZeroManifoldThroughEveryPoint)
{
  const auto points = load ("bunny00.off");
  const WrapResult r = computeWrap (points, rawOutput ());
  const SurfaceReport s = describeSurface ({r.surface.triangles.begin (), r.surface.triangles.end ()});
  EXPECT_TRUE (s.closed_manifold);
  EXPECT_TRUE (s.consistently_oriented);
  EXPECT_EQ (s.components, 1u);
  EXPECT_EQ (s.euler, 2);
  EXPECT_EQ (s.vertices, points.size ());
}

TEST (RealData, KittenScanAndFandiskModelKeepTheInvariants)
{
  for (const std::string name : {"kitten.xyz", "fandisk.off"})
  {
    SCOPED_TRACE (name);
    const auto points = load (name);
    const WrapResult r = computeWrap (points, rawOutput ());
    expectWrapInvariants (r);
    std::set<PointIndex> on_w;
    for (const auto& t : r.surface.triangles)
      on_w.insert (t.begin (), t.end ());
    EXPECT_GT (on_w.size (), points.size () * 9 / 10) << "a scan of a closed surface should be mostly on W";
    if (name == "fandisk.off")
      EXPECT_GT (r.statistics.perturbations, 0u) << "the CAD model has exact ties";
  }
}

TEST (RealData, FrontDeletionOnTheCowLeavesNoSinkThatCouldReachTheSurface)
{
  // On the cow, trials that stay inside at first reach the surface after later deletions: the
  // deletion must try them again, and the end state must be a fixpoint.
  const auto points = load ("cow.off");
  const Pipeline cow (points);
  std::size_t tried = 0;
  for (const double k : {2.0, 3.0, 4.0})
  {
    SCOPED_TRACE ("radius-rel " + std::to_string (k));
    tried += expectFrontDeletionIsAFixpoint (cow, std::pow (k * medianSpacing (points), 2));
  }
  EXPECT_GT (tried, 0u);
}

TEST (RealData, BunnyQuantisedToAMillimetreGridKeepsTheInvariants)
{
  // bunny00.off is one unit across; the real bunny is about 15 cm. Rounding to its millimetres
  // (1/150 of a unit) makes a grid full of exact ties and duplicates, as a quantising sensor does.
  auto points = load ("bunny00.off");
  for (auto& p : points)
    for (double& c : p)
      c = std::round (c * 150.0) / 150.0;
  const WrapResult r = computeWrap (points, rawOutput ());
  EXPECT_GT (r.statistics.points_duplicate, 0u);
  EXPECT_GT (r.statistics.perturbations, 0u);
  expectWrapInvariants (r);
}

} // namespace
} // namespace pcl_wrap::test

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
// The default surface's labels are flooded beside the construction, or, when a sample of the
// points is a single layer, only if the output asks for them. When they are computed never
// changes the output.
#include "support/samplers.h"
#include "wrap_engine.h"

#include <pcl_wrap/compute_wrap.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

namespace
{

using namespace pcl_wrap;
using namespace pcl_wrap::test;

/** The output's triangles, and whether the points were a single layer, with the labels started
  * with the construction or left until needed. */
std::pair<std::vector<std::array<PointIndex, 3>>, bool>
surfaceWith (const std::vector<Point3>& points, bool label_now, const WrapParameters& parameters = WrapParameters ())
{
  const std::vector<double> no_weights; // the engine keeps a reference: not a temporary
  detail::WrapEngine engine (points, no_weights, parameters);
  engine.selectInput ();
  engine.triangulate ();
  engine.startDefaultSurface (label_now);
  engine.buildComplex ();
  engine.classify ();
  engine.collapse ();
  engine.computeFiltration ();
  engine.deleteSinks ();
  engine.extractSurface ();
  engine.report ();
  const WrapResult& r = engine.result ();
  return {{r.surface.triangles.begin (), r.surface.triangles.end ()}, r.statistics.single_layer};
}

void
expectSameEitherWay (const std::vector<Point3>& points, bool single_layer,
                     const WrapParameters& parameters = WrapParameters ())
{
  const auto now = surfaceWith (points, true, parameters), later = surfaceWith (points, false, parameters);
  EXPECT_FALSE (now.first.empty ());
  EXPECT_EQ (now.second, single_layer);
  EXPECT_EQ (later.second, single_layer);
  EXPECT_EQ (now.first, later.first);
}

bool
ran (const WrapResult& r, const std::string& stage)
{
  return std::any_of (r.statistics.timings.begin (), r.statistics.timings.end (),
                      [&] (const StageTiming& t) { return t.stage == stage; });
}

TEST (LabelSchedule, ClosedObjectsComeOutTheSame)
{
  // The labels a closed object needs are flooded after X when they were not started before.
  expectSameEitherWay (sphereSample (4000, 1), false);
  expectSameEitherWay (torusSample (4000, 2), false);
}

TEST (LabelSchedule, SingleLayersComeOutTheSame)
{
  std::vector<Point3> terrain = terrainSample (5000, 3);
  expectSameEitherWay (terrain, true);
  std::mt19937_64 random (4);
  std::normal_distribution<double> noise (0.0, 0.01);
  for (Point3& p : terrain)
    p[2] += noise (random);
  expectSameEitherWay (terrain, true);
  WrapParameters closed;
  closed.output = Output::closed;
  expectSameEitherWay (terrain, true, closed);
  WrapParameters seen;
  seen.viewpoint = std::array<double, 3>{0.0, 0.0, -5.0};
  expectSameEitherWay (terrain, true, seen);
}

TEST (LabelSchedule, AFewPointsWhoseVotesEncloseNothingAreTheirHull)
{
  // A box's corners around its centre: X is a web of triangles through the centre, but the
  // output is the box, either way.
  std::vector<Point3> box;
  for (int i = 0; i < 8; ++i)
    box.push_back ({double (i & 1), 1.1 * double ((i >> 1) & 1), 1.3 * double ((i >> 2) & 1)});
  box.push_back ({0.5, 0.55, 0.65});
  expectSameEitherWay (box, false);
}

TEST (LargeCloud, ASingleLayerIsNotLabelledAndAClosedObjectIs)
{
  const WrapResult terrain = computeWrap (terrainSample (detail::DefaultSurface::LABEL_ON_DEMAND_FROM, 5));
  EXPECT_TRUE (terrain.statistics.single_layer);
  EXPECT_TRUE (ran (terrain, "sample"));
  EXPECT_FALSE (ran (terrain, "votes") || ran (terrain, "labelling")) << "a single layer needs no labels";

  const WrapResult sphere = computeWrap (sphereSample (detail::DefaultSurface::LABEL_ON_DEMAND_FROM, 6));
  EXPECT_FALSE (sphere.statistics.single_layer);
  EXPECT_TRUE (ran (sphere, "sample") && ran (sphere, "votes") && ran (sphere, "labelling"));
}

} // namespace

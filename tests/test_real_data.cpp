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
#include <map>
#include <numeric>
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

TEST (RealData, RawManifoldKeepsTheCowsSheetsWhole)
{
  // The cow's W has sheets running through pinch edges. Split as the boundary of a thickened X, a
  // sheet stays one piece with its two sides. A triangle becomes a closed two-triangle "pillow"
  // of its own only if W has it alone (no other triangle on any of its edges), or where its
  // edges had to be glued across X (two pockets of the outside touching along one): rarely.
  const auto points = load ("cow.off");
  const WrapResult w = computeWrap (points, rawOutput ());
  WrapParameters parameters = rawOutput ();
  parameters.manifold = true;
  const WrapResult m = computeWrap (points, parameters);
  ASSERT_GT (m.statistics.sheet_triangles_doubled, 0u);
  const auto original = [&] (PointIndex v) { return v < points.size () ? v : m.copies.at (v - points.size ()); };
  std::map<std::pair<PointIndex, PointIndex>, int> w_edge_uses;
  for (const auto& t : w.surface.triangles)
    for (int i = 0; i < 3; ++i)
      ++w_edge_uses[std::minmax (t[i], t[(i + 1) % 3])];
  // Components of the split, joined along its edges.
  const std::size_t n = m.surface.triangles.size ();
  std::vector<std::size_t> parent (n);
  std::iota (parent.begin (), parent.end (), 0);
  const auto find = [&] (std::size_t a) {
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  };
  std::map<std::pair<PointIndex, PointIndex>, std::size_t> first_on_edge;
  for (std::size_t k = 0; k < n; ++k)
    for (int i = 0; i < 3; ++i)
    {
      const auto& t = m.surface.triangles[k];
      const auto [at, is_new] = first_on_edge.emplace (std::minmax (t[i], t[(i + 1) % 3]), k);
      if (!is_new)
        parent[find (k)] = find (at->second);
    }
  std::map<std::size_t, std::vector<std::size_t>> components;
  for (std::size_t k = 0; k < n; ++k)
    components[find (k)].push_back (k);
  std::size_t pillows = 0;
  for (const auto& [root, members] : components)
  {
    if (members.size () != 2)
      continue;
    const auto& t = m.surface.triangles[members[0]];
    bool alone_in_w = true;
    for (int i = 0; i < 3; ++i)
      alone_in_w = alone_in_w && w_edge_uses[std::minmax (original (t[i]), original (t[(i + 1) % 3]))] == 1;
    pillows += !alone_in_w;
  }
  EXPECT_LE (20 * pillows, m.statistics.sheet_triangles_doubled) << pillows << " pillows";
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

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// pcl_wrap_mpi's answer to "may one of your points be in this reach?" (docs/mpi.md, "Complete
// stars"), against every point asked one by one: never no where a point is in the reach.
#include "tile_search.h"

#include "delaunay/cgal_kernel.h"
#include "support/samplers.h"
#include "util/distance.h"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <utility>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

/** The reach of the tetrahedron \a p, positively oriented first. */
mpi::TileReach
reachOf (std::array<Point3, 4> p)
{
  const auto bare = [] (const Point3& q) { return detail::BarePoint (q[0], q[1], q[2]); };
  if (CGAL::orientation (bare (p[0]), bare (p[1]), bare (p[2]), bare (p[3])) == CGAL::NEGATIVE)
    std::swap (p[2], p[3]);
  return mpi::TileReach::ofTetrahedron (p, {0, 0, 0, 0}, 0);
}

TEST (TileSearch, NeverSaysNoWhereAPointIsInTheBallOnAThinShell)
{
  // A thin shell: the balls of four points far apart on it are nearly the shell and meet every
  // box of the tree (the nearest point answers them); those of four near ones are small.
  const std::vector<Point3> shell = sphereSample (6000, 9, 1e-3);
  std::vector<Point3> theirs, mine;
  for (const Point3& p : shell)
    (p[0] > 0 ? theirs : mine).push_back (p);
  std::mt19937 random (4);
  std::vector<mpi::TileReach> reaches;
  for (int k = 0; k < 2000; ++k)
  {
    std::array<Point3, 4> p;
    const Point3 centre = mine[random () % mine.size ()];
    for (Point3& q : p)
      do
        q = mine[random () % mine.size ()];
      while (k % 2 == 0 && detail::squaredDistance (q, centre) > 0.01);
    const auto bare = [] (const Point3& q) { return detail::BarePoint (q[0], q[1], q[2]); };
    if (CGAL::orientation (bare (p[0]), bare (p[1]), bare (p[2]), bare (p[3])) != CGAL::COPLANAR)
      reaches.push_back (reachOf (p));
  }
  std::vector<const mpi::TileReach*> asked;
  for (const mpi::TileReach& reach : reaches)
    asked.push_back (&reach);
  mpi::TileSearch search (theirs);
  const std::vector<std::uint8_t> answer = search.anyMayBeIn (asked);

  std::size_t held = 0, told_no = 0;
  for (std::size_t i = 0; i < reaches.size (); ++i)
  {
    bool holds = false;
    for (const Point3& q : theirs)
    {
      mpi::Box point;
      point.add (q);
      holds = holds || reaches[i].mayMeet (point);
    }
    held += holds;
    told_no += !answer[i];
    if (holds)
      EXPECT_TRUE (answer[i]) << "reach " << i << " holds a point";
  }
  EXPECT_GT (search.byNearest (), 200u) << "the nearest point answered too few to test it";
  EXPECT_GT (held, 200u);
  EXPECT_GT (told_no, 200u) << "a search that always says yes";
}

} // namespace
} // namespace pcl_wrap::test

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The connected parts of a labelled solid (docs/surface.md §2): the parts found with the outside's,
// kept up to date as voids fill, are the parts found afresh; and the local test of whether a
// change keeps the solid in one part never says yes to a solid in pieces.
#include "surface/solid_parts.h"
#include "surface/solid_voids.h"
#include "support/pipeline.h"
#include "support/random_labels.h"
#include "support/samplers.h"
#include "util/distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

TEST (SolidParts, PartsKeptUpAsVoidsFillAreThePartsFoundAfresh)
{
  const Pipeline p (cubeSample (3000, 5));
  const std::size_t n = p.complex.size (3);
  std::mt19937 random (7);
  for (int trial = 0; trial < 10; ++trial)
  {
    detail::SolidLabels labels = randomLabels (n, 60, random);
    std::vector<std::uint8_t> moved (n, 0);
    detail::SideParts sides (p.tetrahedra, labels.inside);
    const std::vector<std::uint32_t> filled = detail::fillUnsampledVoids (p.tetrahedra, labels, moved, sides);
    ASSERT_FALSE (filled.empty ()) << "trial " << trial << ": no void filled";
    const detail::SolidParts kept = sides.solid (labels.inside);
    const detail::SolidParts afresh = detail::solidParts (p.tetrahedra, labels.inside);
    ASSERT_GT (afresh.size.size (), 1u);
    EXPECT_EQ (kept.part, afresh.part) << "trial " << trial;
    EXPECT_EQ (kept.size, afresh.size) << "trial " << trial;
  }
}

TEST (SolidParts, StaysOnePartOnlyWhenItIs)
{
  // A ball of tetrahedra, then a few tetrahedra change side: at its surface (a solid mostly still
  // in one part) or anywhere (tetrahedra on their own, pieces cut off). Yes must mean one part;
  // both answers must come up, and yes for most changes at the surface that keep one part.
  const Pipeline p (cubeSample (3000, 9));
  const std::size_t n = p.complex.size (3);
  std::vector<std::uint8_t> ball (n, 0);
  for (std::uint32_t t = 0; t < n; ++t)
  {
    Point3 centroid{0, 0, 0};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k)
        centroid[k] += p.points[p.complex.vertex (3, t, i)][k] / 4;
    const double r = detail::distance (centroid, Point3{0, 0, 0});
    ball[t] = r < 0.6;
  }
  const detail::SolidParts parts = detail::solidParts (p.tetrahedra, ball); // its largest part
  const auto largest = std::max_element (parts.size.begin (), parts.size.end ()) - parts.size.begin ();
  for (std::uint32_t t = 0; t < n; ++t)
    ball[t] = parts.part[t] == largest;
  ASSERT_EQ (detail::solidParts (p.tetrahedra, ball).size.size (), 1u);
  std::vector<std::uint32_t> at_surface; // a facet across it
  for (std::uint32_t t = 0; t < n; ++t)
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = p.tetrahedra.neighbour (t, i);
      if (u != detail::OUTSIDE_HULL && ball[u] != ball[t])
      {
        at_surface.push_back (t);
        break;
      }
    }
  std::mt19937 random (11);
  int yes = 0, no = 0, one_at_surface = 0, yes_at_surface = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    std::vector<std::uint8_t> after = ball;
    const int changes = 1 + random () % 40;
    for (int c = 0; c < changes; ++c)
    {
      const std::uint32_t t =
          trial % 2 ? at_surface[random () % at_surface.size ()] : static_cast<std::uint32_t> (random () % n);
      after[t] ^= 1u;
    }
    std::vector<std::uint32_t> changed;
    for (std::uint32_t t = 0; t < n; ++t)
      if (after[t] != ball[t])
        changed.push_back (t);
    const bool one = detail::solidParts (p.tetrahedra, after).size.size () == 1;
    const bool says_one = detail::staysOnePart (p.tetrahedra, after, changed);
    if (says_one)
      EXPECT_TRUE (one) << "trial " << trial;
    yes += says_one;
    no += !says_one && !one;
    one_at_surface += trial % 2 && one;
    yes_at_surface += trial % 2 && says_one;
  }
  EXPECT_GT (no, 20);
  EXPECT_GT (one_at_surface, 20);
  EXPECT_GT (yes_at_surface, one_at_surface * 3 / 4) << yes_at_surface << " of " << one_at_surface;
  EXPECT_GT (yes, 20);
}

} // namespace
} // namespace pcl_wrap::test

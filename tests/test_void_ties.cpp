// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// Ties across a void (docs/surface.md, "Ties across a void"): a ball inside a hollow sphere, tied
// to the sphere's inner wall by a pillar of tetrahedra across the empty gap, comes apart; a hollow
// ball, a ball with no tie, and a solid with no void keep every label.
#include "surface/solid_parts.h"
#include "surface/solid_voids.h"
#include "surface/void_ties.h"
#include "support/pipeline.h"
#include "support/samplers.h"
#include "util/distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

/** Points on concentric spheres of the radii \a radii, \a counts points each. */
std::vector<Point3>
concentricSpheres (const std::vector<double>& radii, const std::vector<std::size_t>& counts)
{
  std::vector<Point3> points;
  for (std::size_t k = 0; k < radii.size (); ++k)
    for (const Point3& q : sphereSample (counts[k], 7 + unsigned (k)))
      points.push_back ({q[0] * radii[k], q[1] * radii[k], q[2] * radii[k]});
  return points;
}

/** The sphere (an index into \a radii) that vertex \a v lies on. */
std::size_t
shellOf (const Pipeline& p, std::uint32_t v, const std::vector<double>& radii)
{
  const double r = detail::distance (p.points[v], Point3{0, 0, 0});
  std::size_t nearest = 0;
  for (std::size_t k = 1; k < radii.size (); ++k)
    if (std::fabs (r - radii[k]) < std::fabs (r - radii[nearest]))
      nearest = k;
  return nearest;
}

/** The spheres that the corners of tetrahedron \a t lie on. */
std::set<std::size_t>
shellsOf (const Pipeline& p, std::uint32_t t, const std::vector<double>& radii)
{
  std::set<std::size_t> shells;
  for (int i = 0; i < 4; ++i)
    shells.insert (shellOf (p, p.complex.vertex (3, t, i), radii));
  return shells;
}

/** Labels of the solid between spheres 0 and 1 (a thick hollow sphere), with, if \a ball, the
  * inside of sphere 2, and, if \a pillar, the tetrahedra between spheres 1 and 2 whose centroids
  * lie within 0.12 of the positive z-axis. */
detail::SolidLabels
nestedLabels (const Pipeline& p, const std::vector<double>& radii, bool ball, bool pillar)
{
  const std::size_t n = p.complex.size (3);
  detail::SolidLabels labels;
  for (std::uint32_t t = 0; t < n; ++t)
  {
    const std::set<std::size_t> shells = shellsOf (p, t, radii);
    Point3 centroid{0, 0, 0};
    for (int i = 0; i < 4; ++i)
      for (int d = 0; d < 3; ++d)
        centroid[d] += p.points[p.complex.vertex (3, t, i)][d] / 4;
    const bool wall = shells.count (0) > 0, in_ball = shells == std::set<std::size_t>{2};
    const bool in_pillar = !wall && !in_ball && centroid[2] > 0 && std::hypot (centroid[0], centroid[1]) < 0.12;
    labels.inside.push_back (wall || (ball && in_ball) || (pillar && in_pillar));
    labels.margin.push_back (1.0f);
  }
  return labels;
}

const std::vector<double> RADII{1.0, 0.7, 0.4};

TEST (VoidTies, APillarAcrossAVoidIsCutAndNoMoveTiesItAgain)
{
  const Pipeline p (concentricSpheres (RADII, {3000, 1500, 600}));
  const std::size_t n = p.complex.size (3);
  detail::SolidLabels labels = nestedLabels (p, RADII, true, true);
  std::vector<std::uint8_t> moved (n, 0);
  detail::SideParts sides (p.tetrahedra, labels.inside, detail::SideParts::Sides::outside);
  std::vector<std::uint32_t> in_voids;
  detail::fillUnsampledVoids (p.tetrahedra, labels, moved, sides, &in_voids);
  std::fill (moved.begin (), moved.end (), 0);
  const detail::SolidLabels before = labels;
  std::size_t ties = 0;
  for (std::uint32_t t = 0; t < n; ++t)
    ties += before.inside[t] && shellsOf (p, t, RADII) == std::set<std::size_t>{1, 2};
  ASSERT_GT (ties, 0u) << "no pillar";
  ASSERT_EQ (detail::solidParts (p.tetrahedra, before.inside).size.size (), 1u) << "the pillar ties nothing";

  const std::vector<std::uint32_t> cut =
      detail::cutTiesAcrossVoids (p.tetrahedra, p.points, in_voids, labels, moved, sides);

  EXPECT_EQ (cut.size (), ties);
  for (std::uint32_t t = 0; t < n; ++t)
  {
    const bool tie = before.inside[t] && shellsOf (p, t, RADII) == std::set<std::size_t>{1, 2};
    EXPECT_EQ (labels.inside[t], before.inside[t] && !tie) << "tetrahedron " << t;
    EXPECT_EQ (moved[t], tie);
    if (tie) // nor may a later move take it inside again
      EXPECT_FALSE (labels.oneGroup (p.complex.vertices (3, t)));
  }
  // The ball and the wall are apart.
  const detail::SolidParts parts = detail::solidParts (p.tetrahedra, labels.inside);
  std::set<std::uint32_t> ball_parts, wall_parts;
  for (std::uint32_t t = 0; t < n; ++t)
  {
    const std::set<std::size_t> shells = shellsOf (p, t, RADII);
    if (shells == std::set<std::size_t>{2})
      ball_parts.insert (parts.part[t]);
    else if (shells.count (0))
      wall_parts.insert (parts.part[t]);
  }
  EXPECT_EQ (ball_parts.size (), 1u);
  EXPECT_EQ (wall_parts.size (), 1u);
  EXPECT_NE (ball_parts, wall_parts);
  // The ball and the inner wall face each other across the void; the outer wall faces nothing.
  ASSERT_EQ (labels.facing.size (), p.complex.numVertices ());
  std::set<std::uint32_t> objects[3];
  for (std::uint32_t v = 0; v < p.complex.numVertices (); ++v)
    objects[shellOf (p, v, RADII)].insert (labels.facing[v]);
  EXPECT_EQ (objects[0], std::set<std::uint32_t>{detail::SolidLabels::NOT_FACING});
  ASSERT_EQ (objects[1].size (), 1u);
  ASSERT_EQ (objects[2].size (), 1u);
  EXPECT_NE (*objects[1].begin (), detail::SolidLabels::NOT_FACING);
  EXPECT_NE (*objects[2].begin (), detail::SolidLabels::NOT_FACING);
  EXPECT_NE (*objects[1].begin (), *objects[2].begin ());
}

TEST (VoidTies, AVoidWithOneObjectAroundItOrNoVoidHasNothingToCut)
{
  // A hollow ball (the void's surface is one sphere's points), a ball in a hollow sphere with no
  // tie, a solid ball (no void): no label changes, and only the untied ball is marked facing.
  const Pipeline p (concentricSpheres (RADII, {3000, 1500, 600}));
  const std::size_t n = p.complex.size (3);
  struct Case
  {
    const char* name;
    detail::SolidLabels labels;
    bool facing;
  };
  detail::SolidLabels solid;
  for (std::uint32_t t = 0; t < n; ++t)
  {
    solid.inside.push_back (1);
    solid.margin.push_back (1.0f);
  }
  for (Case c : {Case{"hollow ball", nestedLabels (p, RADII, false, false), false},
                 Case{"ball, untied", nestedLabels (p, RADII, true, false), true}, Case{"solid ball", solid, false}})
  {
    std::vector<std::uint8_t> moved (n, 0);
    detail::SideParts sides (p.tetrahedra, c.labels.inside, detail::SideParts::Sides::outside);
    std::vector<std::uint32_t> in_voids;
    detail::fillUnsampledVoids (p.tetrahedra, c.labels, moved, sides, &in_voids);
    EXPECT_EQ (in_voids.empty (), std::string (c.name) == "solid ball") << c.name;
    std::fill (moved.begin (), moved.end (), 0);
    const std::vector<std::uint8_t> inside = c.labels.inside;
    EXPECT_TRUE (detail::cutTiesAcrossVoids (p.tetrahedra, p.points, in_voids, c.labels, moved, sides).empty ())
        << c.name;
    EXPECT_EQ (c.labels.inside, inside) << c.name;
    EXPECT_EQ (moved, std::vector<std::uint8_t> (n, 0)) << c.name;
    EXPECT_EQ (!c.labels.facing.empty (), c.facing) << c.name;
  }
}

} // namespace
} // namespace pcl_wrap::test

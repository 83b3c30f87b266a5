// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The voids of a labelled solid (docs/surface.md §2): a bubble of a few tetrahedra is filled, a
// void whose points show an inner surface stays, and the outside is never touched.
#include "surface/solid_join.h"
#include "surface/solid_voids.h"
#include "support/pipeline.h"
#include "support/random_labels.h"
#include "support/samplers.h"
#include "util/distance.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

TEST (SolidVoids, FillsABubbleKeepsASampledVoidAndTheOutside)
{
  const Pipeline p (cubeSample (3000, 11));
  const detail::SimplicialComplex& complex = p.complex;
  const std::size_t n = complex.size (3);
  // The bubble: the star of the vertex nearest one corner's inner point; the sampled void: every
  // tetrahedron with a corner within 0.35 of the opposite one; the outside: every tetrahedron
  // with a facet on the hull.
  const Point3 bubble_at{-0.4, -0.4, -0.4}, void_at{0.4, 0.4, 0.4};
  std::uint32_t centre = 0;
  for (std::uint32_t v = 1; v < complex.numVertices (); ++v)
    if (detail::distance (p.points[v], bubble_at) < detail::distance (p.points[centre], bubble_at))
      centre = v;
  enum Region : std::uint8_t
  {
    SOLID,
    BUBBLE,
    VOID,
    OUTSIDE
  };
  std::vector<std::uint8_t> region (n, SOLID);
  std::set<std::uint32_t> bubble_vertices, void_vertices;
  for (std::uint32_t t = 0; t < n; ++t)
  {
    bool hull = false, near_void = false, has_centre = false;
    for (int i = 0; i < 4; ++i)
    {
      hull = hull || p.tetrahedra.neighbour (t, i) == detail::OUTSIDE_HULL;
      near_void = near_void || detail::distance (p.points[complex.vertex (3, t, i)], void_at) < 0.35;
      has_centre = has_centre || complex.vertex (3, t, i) == centre;
    }
    region[t] = hull ? OUTSIDE : near_void ? VOID : has_centre ? BUBBLE : SOLID;
    for (int i = 0; i < 4; ++i)
      if (region[t] == BUBBLE)
        bubble_vertices.insert (complex.vertex (3, t, i));
      else if (region[t] == VOID)
        void_vertices.insert (complex.vertex (3, t, i));
  }
  for (std::uint32_t t = 0; t < n; ++t) // the regions are apart: only the solid between them
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = p.tetrahedra.neighbour (t, i);
      if (u != detail::OUTSIDE_HULL && region[t] != SOLID && region[u] != SOLID)
        ASSERT_EQ (region[t], region[u]);
    }
  ASSERT_LT (bubble_vertices.size (), detail::FRAGMENT_VERTICES);
  ASSERT_GE (void_vertices.size (), detail::FRAGMENT_VERTICES);

  detail::SolidLabels labels;
  for (std::uint32_t t = 0; t < n; ++t)
  {
    labels.inside.push_back (region[t] == SOLID);
    labels.margin.push_back (1.0f);
  }
  std::vector<std::uint8_t> moved (n, 0);
  const std::vector<std::uint32_t> filled = detail::fillUnsampledVoids (p.tetrahedra, labels, moved);

  std::size_t bubble = 0;
  for (std::uint32_t t = 0; t < n; ++t)
  {
    bubble += region[t] == BUBBLE;
    EXPECT_EQ (labels.inside[t], region[t] == SOLID || region[t] == BUBBLE) << "tetrahedron " << t;
    EXPECT_EQ (moved[t], region[t] == BUBBLE);
  }
  EXPECT_EQ (filled.size (), bubble);
}

TEST (SolidVoids, AfterAFewMovesTheSearchNearThemFillsWhatTheWholeSearchFills)
{
  // A solid of random labels has voids of every size; once the small ones are filled, a few
  // tetrahedra change side (some making new voids, some splitting or opening old ones), and the
  // search near them must fill exactly what a search of the whole solid fills.
  const Pipeline p (cubeSample (3000, 5));
  const std::size_t n = p.complex.size (3);
  std::mt19937 random (3);
  for (int trial = 0; trial < 20; ++trial)
  {
    detail::SolidLabels labels = randomLabels (n, 70, random);
    std::vector<std::uint8_t> moved (n, 0);
    detail::fillUnsampledVoids (p.tetrahedra, labels, moved);
    std::vector<std::uint32_t> changed;
    for (std::uint32_t t = 0; t < n; ++t)
      if (random () % 100 < 3)
      {
        labels.inside[t] ^= 1u;
        changed.push_back (t);
      }
    detail::SolidLabels whole = labels, near = labels;
    std::vector<std::uint8_t> moved_whole (n, 0), moved_near (n, 0);
    const std::vector<std::uint32_t> filled_whole = detail::fillUnsampledVoids (p.tetrahedra, whole, moved_whole);
    const std::vector<std::uint32_t> filled_near =
        detail::fillUnsampledVoidsNear (p.tetrahedra, near, moved_near, changed);
    ASSERT_FALSE (filled_whole.empty ()) << "trial " << trial << ": no void to find";
    EXPECT_EQ (filled_near, filled_whole) << "trial " << trial;
    EXPECT_EQ (near.inside, whole.inside);
    EXPECT_EQ (moved_near, moved_whole);
  }
}

} // namespace
} // namespace pcl_wrap::test

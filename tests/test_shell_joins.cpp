// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The join of a two-sided shell's pieces that meet only along an edge (docs/surface.md §4).
#include "wrap/manifold_split.h"
#include "surface/shell_joins.h"
#include "support/topology.h"

#include <gtest/gtest.h>

#include <vector>

namespace pcl_wrap::test
{
namespace
{

/** \a k tetrahedra's boundaries that all have the edge (0, 1), each through its own copies of 0
  * and 1 but the first: k closed pieces that meet only along that edge, as a pinch split leaves
  * triangles hanging from a scan's rim. Vertices 2 + 2i and 3 + 2i are piece i's own. */
detail::ManifoldSplit
piecesOnOneEdge (std::uint32_t k)
{
  const std::uint32_t nv = 2 + 2 * k;
  detail::ManifoldSplit split;
  for (std::uint32_t i = 0; i < k; ++i)
  {
    std::uint32_t a = 0, b = 1;
    if (i > 0)
    {
      a = nv + static_cast<std::uint32_t> (split.copy_of.size ());
      b = a + 1;
      split.copy_of.insert (split.copy_of.end (), {0, 1});
    }
    const std::uint32_t u = 2 + 2 * i, w = 3 + 2 * i;
    // The tetrahedron (a, b, u, w), its facets oriented outward.
    split.triangles.push_back ({b, u, w});
    split.triangles.push_back ({a, w, u});
    split.triangles.push_back ({a, b, w});
    split.triangles.push_back ({a, u, b});
  }
  return split;
}

TEST (ShellJoins, PiecesOnOneEdgeBecomeOneSphere)
{
  for (std::uint32_t k : {2u, 3u, 5u})
  {
    SCOPED_TRACE (k);
    detail::ManifoldSplit split = piecesOnOneEdge (k);
    const std::uint32_t nv = 2 + 2 * k;
    ASSERT_EQ (describeSurface ({split.triangles.begin (), split.triangles.end ()}).components, k);

    EXPECT_EQ (detail::joinAlongSharedEdges (split, nv), k - 1);

    const SurfaceReport s = describeSurface ({split.triangles.begin (), split.triangles.end ()});
    EXPECT_TRUE (s.closed_manifold);
    EXPECT_TRUE (s.consistently_oriented);
    EXPECT_EQ (s.components, 1u);
    EXPECT_EQ (s.euler, 2) << "one sphere";
    EXPECT_EQ (split.triangles.size (), 4 * k);
    // The edge every piece had has left the surface; each point is on it once.
    for (const auto& t : split.triangles)
    {
      int ends = 0;
      for (std::uint32_t v : t)
      {
        ASSERT_LT (v, nv + split.copy_of.size ());
        const std::uint32_t base = v < nv ? v : split.copy_of.at (v - nv);
        ends += base < 2;
      }
      EXPECT_LT (ends, 2) << "a triangle still on the shared edge";
    }
    EXPECT_EQ (s.vertices, nv);
  }
}

TEST (ShellJoins, LeavesOtherSurfacesAsTheyAre)
{
  // One piece: nothing to join.
  detail::ManifoldSplit one = piecesOnOneEdge (1);
  const auto triangles = one.triangles;
  EXPECT_EQ (detail::joinAlongSharedEdges (one, 4), 0u);
  EXPECT_EQ (one.triangles, triangles);

  // Two tetrahedra that share a third point as well are one piece already: nothing to join.
  detail::ManifoldSplit two = piecesOnOneEdge (2);
  for (auto& t : two.triangles)
    for (std::uint32_t& v : t)
      if (v == 4)
        v = 2; // piece 1's u is piece 0's u
  const auto before = two.triangles;
  EXPECT_EQ (detail::joinAlongSharedEdges (two, 6), 0u);
  EXPECT_EQ (two.triangles, before);
}

} // namespace
} // namespace pcl_wrap::test

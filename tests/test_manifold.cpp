// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The manifold output option (docs/design.md §8): W split where it touches itself is a closed,
// oriented combinatorial 2-manifold made of W's own triangles, with copies of split points
// appended after the input points.
#include "support/degenerate_samples.h"
#include "support/samplers.h"
#include "support/topology.h"
#include "support/wrap_checks.h"

#include <pcl_wrap/compute_wrap.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

namespace pcl_wrap::test
{
namespace
{

/** A triangle's points, copies read as the point they copy. */
std::array<PointIndex, 3>
original (const WrapResult& r, std::size_t n, std::array<PointIndex, 3> t)
{
  for (auto& v : t)
    if (v >= n)
      v = r.copies.at (v - n);
  std::sort (t.begin (), t.end ());
  return t;
}

/** The split of \a points is a closed oriented 2-manifold made of W's triangles (a sheet triangle
  * once per side), and splits exactly where W is not a manifold. */
void
expectManifoldSplitOf (const std::vector<Point3>& points, const WrapParameters& base = rawOutput ())
{
  WrapParameters parameters = base;
  const WrapResult w = computeWrap (points, parameters);
  parameters.manifold = true;
  const WrapResult m = computeWrap (points, parameters);
  const std::size_t n = points.size ();
  const SimplexList& triangles = w.complex[2];

  const SurfaceReport s = describeSurface ({m.surface.triangles.begin (), m.surface.triangles.end ()});
  if (!m.surface.triangles.empty ())
  {
    EXPECT_TRUE (s.closed_manifold);
    EXPECT_TRUE (s.consistently_oriented);
  }
  for (PointIndex c : m.copies)
    EXPECT_LT (c, n);
  for (const auto& t : m.surface.triangles)
    for (PointIndex v : t)
      EXPECT_LT (v, n + m.copies.size ());

  // The same triangles: W's, each once, a sheet triangle (no tetrahedron of X on it) twice.
  std::map<std::array<PointIndex, 3>, int> expected, got;
  for (const auto& t : w.surface.triangles)
    ++expected[original (w, n, t)];
  std::size_t sheets = 0;
  const auto tet_faces = apexesOfXTriangles (w);
  for (std::size_t f = 0; f < triangles.size (); ++f)
    if (triangles.in_x[f])
    {
      std::array<PointIndex, 3> t{triangles.vertices[3 * f], triangles.vertices[3 * f + 1],
                                  triangles.vertices[3 * f + 2]};
      std::sort (t.begin (), t.end ());
      if (expected.count (t) && tet_faces.count ({t[0], t[1], t[2]}) == 0)
      {
        ++expected[t];
        ++sheets;
      }
    }
  for (const auto& t : m.surface.triangles)
    ++got[original (m, n, t)];
  EXPECT_EQ (got, expected);
  EXPECT_EQ (m.statistics.sheet_triangles_doubled, sheets);

  // Nothing split where W is already a manifold; something split where it is not.
  const SurfaceReport before = describeSurface ({w.surface.triangles.begin (), w.surface.triangles.end ()});
  EXPECT_EQ (before.closed_manifold && before.consistently_oriented, m.copies.empty () && sheets == 0);
  EXPECT_EQ (m.statistics.pinch_edges_split, pinchEdges (w));
  EXPECT_EQ (m.statistics.pinch_vertices_split > 0, !m.copies.empty ());
}

TEST (Manifold, SealedToriSplitIntoClosedManifolds)
{
  std::size_t split = 0;
  for (unsigned seed = 1; seed <= 6; ++seed)
  {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    expectManifoldSplitOf (torusSample (200, seed));
    WrapParameters manifold = rawOutput ();
    manifold.manifold = true;
    split += computeWrap (torusSample (200, seed), manifold).statistics.pinch_edges_split;
  }
  EXPECT_GT (split, 0u) << "sealed tori touch themselves along pinch edges";
}

TEST (Manifold, RandomCubesWithSheetsAndPinches)
{
  for (unsigned seed = 1; seed <= 8; ++seed)
  {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    expectManifoldSplitOf (cubeSample (400, seed));
  }
}

TEST (Manifold, DegenerateFamilies)
{
  for (const auto& sample : degenerateFamilies ())
  {
    SCOPED_TRACE (sample.name);
    expectManifoldSplitOf (sample.points);
  }
}

TEST (Manifold, AfterSinkDeletion)
{
  WrapParameters deletion = rawOutput ();
  deletion.threshold = Threshold::relativeRadius (3);
  for (unsigned seed = 1; seed <= 3; ++seed)
  {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    expectManifoldSplitOf (doubleTorusSample (1200, seed), deletion);
    deletion.deletion = SinkDeletion::global;
    expectManifoldSplitOf (torusSample (1000, seed), deletion);
    deletion.deletion = SinkDeletion::front;
  }
}

} // namespace
} // namespace pcl_wrap::test

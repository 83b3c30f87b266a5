// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// A triangulation grown in batches reads exactly as the one triangulation of all the points:
// the same tetrahedra in the same order, the same neighbours, vertex ids and hidden points.
#include "support/degenerate_samples.h"
#include "support/samplers.h"

#include "delaunay/regular_triangulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

/** The edges of \a t's top simplices, as pairs of point indices (lower first), ascending. */
std::vector<std::array<std::uint32_t, 2>>
edgesOf (const detail::Triangulation& t)
{
  const auto k = static_cast<std::size_t> (t.dimension + 1);
  std::vector<std::array<std::uint32_t, 2>> edges;
  for (std::size_t s = 0; k >= 2 && s + k <= t.top_simplices.size (); s += k)
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t b = a + 1; b < k; ++b)
      {
        const std::uint32_t p = t.point_of_vertex[t.top_simplices[s + a]],
                            q = t.point_of_vertex[t.top_simplices[s + b]];
        edges.push_back ({std::min (p, q), std::max (p, q)});
      }
  std::sort (edges.begin (), edges.end ());
  edges.erase (std::unique (edges.begin (), edges.end ()), edges.end ());
  return edges;
}

void
expectGrownIsWhole (const std::vector<Point3>& points, const std::vector<double>& weights,
                    const std::vector<std::size_t>& batch_ends, bool equal_weights)
{
  detail::GrowingTriangulation growing (equal_weights);
  std::vector<Point3> so_far;
  std::vector<double> weights_so_far;
  for (std::size_t end : batch_ends)
  {
    const std::size_t first = so_far.size ();
    so_far.insert (so_far.end (), points.begin () + first, points.begin () + end);
    weights_so_far.insert (weights_so_far.end (), weights.begin () + first, weights.begin () + end);
    growing.insert (so_far, weights_so_far, first);
    const detail::Triangulation grown = growing.read (so_far);
    const detail::Triangulation whole = detail::triangulate (so_far, weights_so_far);
    ASSERT_EQ (grown.dimension, whole.dimension);
    EXPECT_EQ (grown.point_of_vertex, whole.point_of_vertex) << "after " << end << " points";
    EXPECT_EQ (grown.hidden, whole.hidden);
    EXPECT_TRUE (grown.top_simplices == whole.top_simplices) << "after " << end << " points";
    EXPECT_TRUE (grown.neighbours == whole.neighbours);
    // Its graph, read alone, is the triangulation's: each edge once.
    std::vector<std::array<std::uint32_t, 2>> edges = growing.edges ();
    std::sort (edges.begin (), edges.end ());
    EXPECT_EQ (edges, edgesOf (whole)) << "after " << end << " points";
  }
}

TEST (GrowingTriangulation, ReadsAsTheWholeTriangulationAfterEachBatch)
{
  // Large enough batches for the threaded insertion, where there are threads.
  const std::vector<Point3> cube = cubeSample (60000, 1);
  expectGrownIsWhole (cube, std::vector<double> (cube.size (), 0.0), {30000, 31000, 60000}, true);
}

TEST (GrowingTriangulation, WeightedWithHiddenPoints)
{
  const std::vector<Point3> points = cubeSample (3000, 2);
  std::mt19937 random (3);
  std::uniform_real_distribution<double> weight (0.0, 4e-3);
  std::vector<double> weights (points.size ());
  for (double& w : weights)
    w = weight (random);
  expectGrownIsWhole (points, weights, {1000, 1100, 2500, 3000}, false);
}

TEST (GrowingTriangulation, CosphericalGridInTwoHalves)
{
  std::vector<Point3> grid = gridSample (8, 8, 8);
  std::shuffle (grid.begin (), grid.end (), std::mt19937 (4));
  expectGrownIsWhole (grid, std::vector<double> (grid.size (), 1.0), {256, 512}, true);
}

TEST (GrowingTriangulation, EdgesOfAFlatGridAreItsTrianglesEdges)
{
  // All on one plane: the top simplices are triangles.
  std::vector<Point3> grid = gridSample (9, 9, 1);
  std::shuffle (grid.begin (), grid.end (), std::mt19937 (5));
  detail::GrowingTriangulation growing (true);
  growing.insert (grid, std::vector<double> (grid.size (), 0.0), 0);
  const detail::Triangulation t = growing.read (grid);
  ASSERT_EQ (t.dimension, 2);
  std::vector<std::array<std::uint32_t, 2>> edges = growing.edges ();
  std::sort (edges.begin (), edges.end ());
  EXPECT_EQ (edges, edgesOf (t));
  EXPECT_EQ (edges.size (), 8u * 9 * 2 + 8u * 8); // the grid's sides and one diagonal per square
}

} // namespace
} // namespace pcl_wrap::test

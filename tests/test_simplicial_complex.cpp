// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The simplicial complex built from the tetrahedra: every face a simplex names is the simplex
// spanned by those vertices, and the edges do not depend on the order the tetrahedra come in.
// (The triangulation gives them grouped by lowest vertex, which lets edge naming skip half its
// bucketing; in any other order every edge instance is bucketed.)
#include "support/samplers.h"

#include "delaunay/input_points.h"
#include "delaunay/regular_triangulation.h"
#include "delaunay/simplicial_complex.h"
#include "delaunay/spacing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

using detail::FilledInParallel;
using detail::SimplexId;
using detail::SimplicialComplex;

/** Every face of every simplex, by mask: its vertices are the masked ones, ascending. */
void
expectFacesAreTheirVertices (const SimplicialComplex& c)
{
  for (int k = 1; k <= c.dimension (); ++k)
    for (SimplexId s = 0; s < c.size (k); ++s)
      for (unsigned mask = 1; mask < detail::fullMask (k); ++mask)
      {
        std::vector<std::uint32_t> expected;
        for (int i = 0; i <= k; ++i)
          if (mask & (1u << i))
            expected.push_back (c.vertex (k, s, i));
        std::sort (expected.begin (), expected.end ());
        const detail::Simplex f = c.face (k, s, mask);
        ASSERT_EQ (f.dim, detail::maskSize (mask) - 1);
        const std::vector<std::uint32_t> got (c.vertices (f.dim, f.id), c.vertices (f.dim, f.id) + f.dim + 1);
        ASSERT_EQ (got, expected) << "face " << mask << " of simplex " << k << ":" << s;
      }
}

std::set<std::array<std::uint32_t, 3>>
triangleSet (const SimplicialComplex& c)
{
  std::set<std::array<std::uint32_t, 3>> out;
  for (SimplexId s = 0; s < c.size (2); ++s)
    out.insert ({c.vertex (2, s, 0), c.vertex (2, s, 1), c.vertex (2, s, 2)});
  return out;
}

TEST (SimplicialComplex, FacesAndEdgesWhateverTheOrderOfTheTetrahedra)
{
  for (unsigned seed = 1; seed <= 3; ++seed)
  {
    const detail::InputPoints input = detail::selectInputPoints (cubeSample (3000, seed), {});
    const detail::Triangulation t = detail::triangulate (input.positions, input.weights);
    ASSERT_EQ (t.dimension, 3);
    const auto n = static_cast<std::uint32_t> (t.point_of_vertex.size ());
    const SimplicialComplex grouped (3, n, t.top_simplices, t.neighbours);

    // The same tetrahedra in a random order, each turned by an even permutation of its
    // vertices (orientation kept), with their neighbours renumbered to match.
    const std::size_t num_tets = t.top_simplices.size () / 4;
    std::mt19937 random (seed);
    std::vector<std::uint32_t> place (num_tets);
    std::iota (place.begin (), place.end (), 0u);
    std::shuffle (place.begin (), place.end (), random);
    constexpr int TURN[3][4] = {{0, 1, 2, 3}, {1, 2, 0, 3}, {2, 3, 0, 1}}; // even permutations
    FilledInParallel<std::uint32_t> top (4 * num_tets), neighbours (4 * num_tets);
    for (std::size_t j = 0; j < num_tets; ++j)
    {
      const int* turn = TURN[random () % 3];
      for (int i = 0; i < 4; ++i)
      {
        top[4 * place[j] + i] = t.top_simplices[4 * j + turn[i]];
        const std::uint32_t u = t.neighbours[4 * j + turn[i]];
        neighbours[4 * place[j] + i] = u == detail::NO_NEIGHBOUR ? u : place[u];
      }
    }
    const SimplicialComplex shuffled (3, n, std::move (top), neighbours);

    expectFacesAreTheirVertices (grouped);
    expectFacesAreTheirVertices (shuffled);
    for (int k = 0; k <= 3; ++k)
      ASSERT_EQ (grouped.size (k), shuffled.size (k)) << "dimension " << k;
    // Edges are numbered in lexicographic order in both, with the same number of cofaces.
    for (SimplexId e = 0; e < grouped.size (1); ++e)
    {
      ASSERT_EQ (grouped.vertex (1, e, 0), shuffled.vertex (1, e, 0)) << "edge " << e;
      ASSERT_EQ (grouped.vertex (1, e, 1), shuffled.vertex (1, e, 1)) << "edge " << e;
      ASSERT_EQ (grouped.cofaceCounts (1)[e], shuffled.cofaceCounts (1)[e]) << "edge " << e;
      ASSERT_TRUE (e == 0 || std::make_pair (grouped.vertex (1, e - 1, 0), grouped.vertex (1, e - 1, 1)) <
                                 std::make_pair (grouped.vertex (1, e, 0), grouped.vertex (1, e, 1)));
    }
    EXPECT_EQ (triangleSet (grouped), triangleSet (shuffled));
    // Euler: V - E + F - T = 1 for a triangulated ball.
    EXPECT_EQ (static_cast<long> (grouped.size (0)) - static_cast<long> (grouped.size (1)) +
                   static_cast<long> (grouped.size (2)) - static_cast<long> (grouped.size (3)),
               1);
  }
}

// One point has no edge, two have no triangle: the start of a dimension with no simplices is a
// range of none, which the nearest-neighbour pass takes as it does a tile of one point. (The
// sanitizer build checks that nothing there indexes an empty array.)
TEST (SimplicialComplex, ADimensionWithNoSimplicesIsAnEmptyRange)
{
  for (const std::vector<Point3>& points : {std::vector<Point3>{{1, 2, 3}}, std::vector<Point3>{{1, 2, 3}, {1, 2, 5}}})
  {
    const detail::InputPoints input = detail::selectInputPoints (points, {});
    const detail::Triangulation t = detail::triangulate (input.positions, input.weights);
    const auto n = static_cast<std::uint32_t> (t.point_of_vertex.size ());
    ASSERT_EQ (n, points.size ());
    ASSERT_EQ (t.dimension, static_cast<int> (n) - 1);
    const SimplicialComplex c (t.dimension, n, t.top_simplices, t.neighbours);
    for (int k = c.dimension () + 1; k <= 3; ++k)
    {
      ASSERT_EQ (c.size (k), 0u) << "dimension " << k;
      EXPECT_EQ (c.vertices (k, 0), c.vertexArray (k).data ()) << "dimension " << k;
    }
    const std::vector<double> nearest =
        detail::nearestNeighbourSquared (c.vertices (1, 0), c.size (1), 1, input.positions);
    ASSERT_EQ (nearest.size (), n);
    for (double d : nearest)
      EXPECT_EQ (d, n == 1 ? INFINITY : 4.0);
    EXPECT_EQ (detail::medianNearestNeighbourDistance (c.vertices (1, 0), c.size (1), 1, input.positions),
               n == 1 ? 0.0 : 2.0);
  }
}

} // namespace
} // namespace pcl_wrap::test

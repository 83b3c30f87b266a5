// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// Weighted points (paper §3): hidden points, equivocal vertices, confident edges; the invariants
// and the exact reference on random weighted sets; configurations worked out by hand.
#include "support/exact_reference.h"
#include "support/flow_checks.h"
#include "support/naive_retraction.h"
#include "support/pipeline.h"
#include "support/samplers.h"
#include "support/wrap_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace pcl_wrap::test
{
namespace
{

using detail::Simplex;

/** Weights uniform in [low, high]. */
std::vector<double>
randomWeights (std::size_t n, double low, double high, unsigned seed)
{
  std::mt19937_64 random (seed);
  std::uniform_real_distribution<double> u (low, high);
  std::vector<double> w (n);
  for (double& x : w)
    x = u (random);
  return w;
}

/** Random point sets with weights both positive and negative, small and comparable to the
  * squared spacing (2 / n^(1/3) in the cube), up to twice that, which hides points. */
struct WeightedSample
{
  std::vector<Point3> points;
  std::vector<double> weights;
};

std::vector<WeightedSample>
weightedSamples (std::size_t n, unsigned seed)
{
  return {{cubeSample (n, seed), randomWeights (n, -0.01, 0.01, seed)},
          {cubeSample (n, seed + 100), randomWeights (n, -0.1, 0.1, seed)},
          {cubeSample (n, seed + 200), randomWeights (n, 0.0, 0.2, seed)},
          {sphereSample (n, seed, 0.05), randomWeights (n, -0.02, 0.05, seed)},
          {cubeSample (n, seed + 300), randomWeights (n, 0.0, 2 * std::pow (2.0 / std::cbrt (double (n)), 2), seed)}};
}

TEST (Weights, ZeroWeightsGiveExactlyTheUnweightedResult)
{
  for (const auto& points : {cubeSample (800, 3), sphereSample (800, 3, 0.01), torusSample (500, 3)})
  {
    const WrapResult plain = computeWrap (points, rawOutput ());
    const WrapResult zero = computeWrap (points, std::vector<double> (points.size (), 0.0), rawOutput ());
    EXPECT_EQ (zero.surface.triangles, plain.surface.triangles);
    EXPECT_EQ (zero.surface.dangling_edges, plain.surface.dangling_edges);
    EXPECT_EQ (zero.statistics.simplices, plain.statistics.simplices);
    for (int k = 0; k <= 3; ++k)
      EXPECT_EQ (zero.complex[k].in_x, plain.complex[k].in_x);
  }
}

TEST (Weights, HiddenPointInsideFourHeavyPoints)
{
  // The origin (weight 0) has an empty power cell: for it to be nearer than every corner p_i of
  // the tetrahedron, every <x, p_i> would have to be at most -3.5, but the p_i sum to 0.
  const std::vector<Point3> points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}, {0, 0, 0}};
  const WrapResult r = computeWrap (points, std::vector<double>{10, 10, 10, 10, 0}, rawOutput ());
  EXPECT_EQ (r.hidden, std::vector<PointIndex> ({4}));
  EXPECT_EQ (r.statistics.points_hidden, 1u);
  EXPECT_EQ (r.surface.triangles.size (), 4u); // the regular tetrahedron is a sink: its 4 faces
  for (const auto& t : r.surface.triangles)
    EXPECT_EQ (std::count (t.begin (), t.end (), 4u), 0);
}

TEST (Weights, LightPointFlowsIntoHeavyOne)
{
  // Edge pq, |pq| = 1, w_p = 0. lambda_p < 0 iff 1 + w_q < w_p: with w_q = -2 the edge is
  // confident with lowest successor q, q is attached (p is inside its sphere: 1 - 0 < 2), and the
  // collapse leaves p alone. With w_q = -0.5 the edge is a sink and stays.
  const std::vector<Point3> points = {{0, 0, 0}, {1, 0, 0}};
  const WrapResult collapsed = computeWrap (points, std::vector<double>{0, -2}, rawOutput ());
  EXPECT_EQ (collapsed.statistics.simplices[0][int (SimplexClass::equivocal)], 1u);
  EXPECT_EQ (collapsed.statistics.simplices[1][int (SimplexClass::confident)], 1u);
  EXPECT_TRUE (collapsed.surface.dangling_edges.empty ());
  EXPECT_EQ (collapsed.surface.isolated_vertices, std::vector<PointIndex> ({0}));

  const WrapResult kept = computeWrap (points, std::vector<double>{0, -0.5}, rawOutput ());
  ASSERT_EQ (kept.surface.dangling_edges.size (), 1u);
  EXPECT_EQ (kept.surface.dangling_edges[0], (std::array<PointIndex, 2>{0, 1}));
}

TEST (Weights, ScaleMultipliesEveryWeight)
{
  const auto points = cubeSample (400, 5);
  const auto weights = randomWeights (400, 0.0, 0.05, 5);
  auto doubled = weights;
  for (double& w : doubled)
    w *= 2;
  WrapParameters scaled = rawOutput ();
  scaled.weight_scale = 2;
  EXPECT_EQ (computeWrap (points, weights, scaled).surface.triangles,
             computeWrap (points, doubled, rawOutput ()).surface.triangles);
  EXPECT_THROW (computeWrap (points, std::vector<double> (3, 0.0), rawOutput ()), std::invalid_argument);
}

TEST (Weights, InvariantsOnRandomWeightedSets)
{
  std::size_t hidden = 0, equivocal_vertices = 0, confident_edges = 0;
  for (std::size_t n : {300u, 1500u})
    for (unsigned seed = 1; seed <= 3; ++seed)
      for (const auto& [points, weights] : weightedSamples (n, seed))
      {
        SCOPED_TRACE ("n " + std::to_string (n) + " seed " + std::to_string (seed));
        const Pipeline p (points, weights);
        expectFlowInvariants (p);
        const WrapResult r = computeWrap (points, weights, rawOutput ());
        expectWrapInvariants (r);
        hidden += r.statistics.points_hidden;
        equivocal_vertices += r.statistics.simplices[0][int (SimplexClass::equivocal)];
        confident_edges += r.statistics.simplices[1][int (SimplexClass::confident)];
        for (const auto& t : r.surface.triangles)
          for (PointIndex v : t)
            EXPECT_FALSE (std::binary_search (r.hidden.begin (), r.hidden.end (), v)) << "a hidden point on W";
      }
  // The samples must reach what only weights can produce.
  EXPECT_GT (hidden, 0u);
  EXPECT_GT (equivocal_vertices, 0u);
  EXPECT_GT (confident_edges, 0u);
}

TEST (Weights, ParallelInsertionHidesTheSamePointsAsOneThread)
{
  // Over 20000 points, so that more than one thread inserts in parallel; heavy weights hide
  // points, and a point hidden by one thread's insertion may have been another's hint.
  const std::size_t n = 25000;
  const auto points = cubeSample (n, 11);
  const auto weights = randomWeights (n, 0.0, 2 * std::pow (2.0 / std::cbrt (double (n)), 2), 11);
  WrapParameters one = rawOutput ();
  one.num_threads = 1;
  const WrapResult reference = computeWrap (points, weights, one);
  ASSERT_GT (reference.hidden.size (), 100u);
  for (unsigned threads : {2u, 0u})
  {
    WrapParameters many = rawOutput ();
    many.num_threads = threads;
    const WrapResult r = computeWrap (points, weights, many);
    EXPECT_EQ (r.hidden, reference.hidden);
    EXPECT_EQ (r.surface.triangles, reference.surface.triangles);
    EXPECT_EQ (r.statistics.simplices, reference.statistics.simplices);
    for (int k = 0; k <= 3; ++k)
    {
      EXPECT_EQ (r.complex[k].vertices, reference.complex[k].vertices);
      EXPECT_EQ (r.complex[k].in_x, reference.complex[k].in_x);
    }
  }
}

TEST (Weights, MatchExactReferenceAndNaiveRetraction)
{
  std::size_t hidden_checked = 0;
  for (unsigned seed = 1; seed <= 4; ++seed)
    for (const auto& [points, weights] : weightedSamples (30, seed))
    {
      SCOPED_TRACE ("seed " + std::to_string (seed));
      const Pipeline p (points, weights);
      std::vector<NaiveSimplex> del;
      forEachSimplex (p, [&] (Simplex s) {
        const std::uint32_t* v = p.complex.vertices (s.dim, s.id);
        const std::vector<std::uint32_t> vertices (v, v + s.dim + 1);
        const ExactClass e = classifyExactly (p.points, p.weights, vertices, p.dimension ());
        ASSERT_FALSE (e.degenerate);
        ASSERT_EQ (p.classification.of (s), e.cls) << "simplex " << s.dim << ":" << s.id;
        ASSERT_EQ (p.classification.lowest_successor[s.dim][s.id], e.lowest_successor_mask);
        // Hidden points never attach: outside the smallest orthosphere of every unattached simplex.
        if (e.cls != SimplexClass::equivocal)
        {
          const ExactSphere sphere = smallestOrthosphere (p.points, p.weights, vertices);
          for (std::size_t h = 0; h < p.hidden_points.size (); ++h, ++hidden_checked)
            ASSERT_TRUE (CGAL::is_positive (power (sphere, p.hidden_points[h], p.hidden_weights[h])));
        }
        NaiveSimplex n{p.tuple (s), e.cls, {}};
        for (int i = 0; i <= s.dim; ++i)
          if (e.lowest_successor_mask & (1u << i))
            n.lowest_successor.push_back (v[i]);
        std::sort (n.lowest_successor.begin (), n.lowest_successor.end ());
        del.push_back (std::move (n));
      });
      const auto reference = naiveRetraction (del, seed);
      for (std::uint64_t order : {0u, 3u})
        ASSERT_EQ (p.retractedX (order), reference);
    }
  EXPECT_GT (hidden_checked, 0u);
}

} // namespace
} // namespace pcl_wrap::test

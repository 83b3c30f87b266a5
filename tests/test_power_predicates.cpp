// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The one geometric predicate (docs/design.md §2) against the exact rational power of the smallest
// orthosphere, on queries placed within a few ulps of the sphere and at scales on both sides of
// the range the double-precision filters accept: a filter may pass a question on to the exact
// computation, never answer it wrongly. Asked one at a time and a whole simplex at once.
#include "support/exact_reference.h"

#include "delaunay/power_predicates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace pcl_wrap::test
{
namespace
{

struct Tally
{
  std::size_t compared = 0, exact_ties = 0;
};

/** \a n random points of spread \a scale around \a offset, then queries at the smallest
  * orthosphere's (weight-free) radius times 1 + k 2^-52 in random directions, each compared
  * with the sign of the exact power. All points carry the weight \a weight. */
void
compareNearSphere (int n, double scale, double offset, double weight, std::mt19937& rng, Tally& tally)
{
  std::uniform_real_distribution<double> unit (-1.0, 1.0);
  std::vector<Point3> points;
  for (int i = 0; i < n; ++i)
    points.push_back ({offset + scale * unit (rng), offset + scale * unit (rng), offset + scale * unit (rng)});
  std::vector<double> weights (n, weight);
  std::vector<std::uint32_t> ids (n);
  for (int i = 0; i < n; ++i)
    ids[i] = static_cast<std::uint32_t> (i);
  const ExactSphere sphere = smallestOrthosphere (points, weights, ids);
  // Radius from the centre to the points, scaled to stay within double range.
  const Rational s (scale);
  const double radius = scale * std::sqrt (CGAL::to_double ((sphere.squared_radius + Rational (weight)) / (s * s)));

  for (const double k : {-4.0, -1.0, 0.0, 1.0, 4.0, -0x1p40, 0x1p40, -0x1p51})
  {
    double d[3], norm = 0.0;
    for (double& x : d)
      x = unit (rng), norm += x * x;
    norm = std::sqrt (norm);
    Point3 q;
    for (int c = 0; c < 3; ++c)
      q[c] = CGAL::to_double (sphere.centre[c]) + radius * (1.0 + k * 0x1p-52) * d[c] / norm;
    std::vector<Point3> with_query = points;
    with_query.push_back (q);
    std::vector<double> query_weights (n + 1, weight);
    const Rational power_of_q = power (sphere, q, weight);
    if (CGAL::is_zero (power_of_q))
    {
      ++tally.exact_ties; // the perturbation decides; tested elsewhere
      continue;
    }
    const detail::PowerPredicates predicates (with_query, query_weights);
    ASSERT_EQ (predicates.insideSmallestOrthosphere (ids.data (), n, static_cast<std::uint32_t> (n)),
               CGAL::is_negative (power_of_q))
        << n << " points, scale " << scale << ", offset " << offset << ", weight " << weight << ", k " << k;
    // The same question asked with all of the simplex (sphere points + q)'s others at once, with
    // q last and first (a tetrahedron's filter treats its first vertex apart).
    for (const bool q_first : {false, true})
    {
      std::vector<std::uint32_t> simplex = ids;
      simplex.insert (q_first ? simplex.begin () : simplex.end (), static_cast<std::uint32_t> (n));
      const int q_slot = q_first ? 0 : n;
      const unsigned inside = predicates.insideOppositeFacets (simplex.data (), n);
      ASSERT_EQ (bool (inside & (1u << q_slot)), CGAL::is_negative (power_of_q))
          << "batched, " << n << " points, scale " << scale << ", q first " << q_first;
      for (int i = 0; i <= n; ++i)
      {
        std::vector<std::uint32_t> facet = simplex;
        facet.erase (facet.begin () + i);
        ASSERT_EQ (bool (inside & (1u << i)), predicates.insideSmallestOrthosphere (facet.data (), n, simplex[i]));
      }
    }
    ++tally.compared;
  }
}

TEST (PowerPredicates, AgreeWithExactPowerNearTheSphereAtEveryScale)
{
  std::mt19937 rng (2026);
  Tally tally;
  for (const double scale : {1.0, 0x1p-100, 0x1p-118, 0x1p-125, 0x1p100, 0x1p118, 0x1p125, 1e-300, 1e300})
    for (const double offset_factor : {0.0, 3.0, 0x1p20})
      for (const int n : {2, 3})
        for (int trial = 0; trial < 60; ++trial)
        {
          const double offset = offset_factor * scale;
          compareNearSphere (n, scale, offset, 0.0, rng, tally);
          if (std::isfinite (scale * scale) && scale * scale > 0)
            compareNearSphere (n, scale, offset, 0.25 * scale * scale, rng, tally); // equal, non-zero
        }
  EXPECT_GT (tally.compared, 30000u);
}

} // namespace
} // namespace pcl_wrap::test

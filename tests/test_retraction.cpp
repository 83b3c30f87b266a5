// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The retraction (docs/design.md §5): the engine against the naive rescanning retraction, order
// independence, X contractible, W = Bd X with its triangles oriented away from X.
#include "wrap/wrap_filtration.h"
#include "support/exact_reference.h"
#include "support/naive_retraction.h"
#include "support/pipeline.h"
#include "support/samplers.h"
#include "support/topology.h"
#include "support/wrap_checks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

namespace pcl_wrap::test
{
namespace
{

using detail::SimplexId;

std::vector<std::vector<Point3>>
shapes (std::size_t n, unsigned seed)
{
  return {cubeSample (n, seed), sphereSample (n, seed, 0.05), torusSample (n, seed)};
}

TEST (Retraction, EqualsNaiveRetractionOnExactClassesInAnyOrder)
{
  std::size_t collapsed_somewhere = 0;
  for (unsigned seed = 1; seed <= 5; ++seed)
    for (const auto& points : shapes (30, seed))
    {
      SCOPED_TRACE ("seed " + std::to_string (seed));
      const Pipeline p (points);
      // The reference sees only the exact rational classification, never the engine's.
      const std::vector<NaiveSimplex> del = naiveComplexWithExactClasses (p);
      const auto reference = naiveRetraction (del, 1);
      for (unsigned order = 2; order <= 4; ++order)
        ASSERT_EQ (naiveRetraction (del, order), reference) << "the naive retraction depends on its order";
      for (std::uint64_t order : {0u, 1u, 7u})
        ASSERT_EQ (p.retractedX (order), reference) << "engine order " << order;
      collapsed_somewhere += reference.size () < del.size ();
    }
  EXPECT_GT (collapsed_somewhere, 0u);
}

TEST (Retraction, IndependentOfTheOrderOfCollapses)
{
  for (const auto& points : shapes (2000, 11))
  {
    const Pipeline p (points);
    const auto x = p.retractedX (0);
    for (std::uint64_t order = 1; order <= 4; ++order)
      EXPECT_EQ (p.retractedX (order), x);
  }
}

TEST (Retraction, FirstRetractionOnAllThreadsEqualsOneOrderOnOneThread)
{
  // The fixed-order first retraction runs on all threads, in chunks of 4096 seeds per
  // dimension: 20000 points give dozens of chunks in every dimension, so threads race for
  // neighbouring pairs. Repeated, as a race would show only sometimes.
  for (const auto& points : shapes (20000, 12))
  {
    const Pipeline p (points);
    const auto one_thread = p.retractedX (5);
    for (int run = 0; run < 3; ++run)
      EXPECT_EQ (p.retractedX (0), one_thread) << "run " << run;
  }
}

/** Per simplex of every dimension: 0 outside \a y, else 1 + its coface count in \a y. */
std::vector<std::uint32_t>
membershipAndCounts (const detail::Subcomplex& y)
{
  std::vector<std::uint32_t> out;
  for (int k = 0; k <= 3; ++k)
    for (SimplexId s = 0; s < y.complex ().size (k); ++s)
      out.push_back (y.contains ({k, s}) ? 1 + y.cofaceCount ({k, s}) : 0);
  return out;
}

TEST (Retraction, RolledBackTrialsLeaveYAsItWas)
{
  // A front deletion's trial deletes sinks and retracts, then may put everything back: Y and
  // every coface count must be as before, or later freeness tests go wrong.
  for (const auto& points : shapes (1500, 13))
  {
    const Pipeline p (points);
    detail::Subcomplex y (p.complex);
    detail::RemovalLog log (p.complex);
    detail::Retraction retraction (y, p.classification, &log);
    retraction.retract ();
    const auto before = membershipAndCounts (y);
    detail::WrapFiltration order;
    detail::orderSinks (p.complex, p.classification, p.points, p.weights, order);
    std::size_t trials = 0, removed = 0;
    for (std::size_t j = 0; j < order.sinks.size () && j < 40; ++j)
    {
      const detail::Simplex sink = order.sinks[j];
      log.beginTrial ();
      if (retraction.deletePrincipal (sink))
      {
        retraction.retractFreed ();
        removed += log.trialRemovals ().size ();
        ++trials;
      }
      log.rollbackTrial (y);
      ASSERT_EQ (membershipAndCounts (y), before) << "after the trial on sink " << trials;
    }
    EXPECT_GT (trials, 5u);
    EXPECT_GT (removed, trials); // the retractions after the deletions removed something too
  }
}

TEST (Retraction, LongFreedRetractionOnAllThreadsEqualsOneOrderOnOneThread)
{
  // Deleting the largest sink of a sphere sample frees the whole inside: that retraction goes on
  // all threads once it is long, sharing one basin, and logs its trial from every thread. Y, the
  // coface counts and the set of logged removals must be those of one thread in a random order,
  // and putting the trial back must restore Y. Repeated, as a race would show only sometimes.
  const Pipeline p (sphereSample (20000, 14, 0.001));
  detail::WrapFiltration order;
  detail::orderSinks (p.complex, p.classification, p.points, p.weights, order, 0.0, 1);
  ASSERT_FALSE (order.sinks.empty ());
  const auto run = [&] (std::uint64_t seed) {
    detail::Subcomplex y (p.complex);
    detail::RemovalLog log (p.complex);
    detail::Retraction retraction (y, p.classification, &log);
    retraction.retract ();
    const auto before = membershipAndCounts (y);
    log.beginTrial ();
    EXPECT_TRUE (retraction.deletePrincipal (order.sinks[0]));
    retraction.retractFreed (seed);
    std::vector<std::pair<int, SimplexId>> removed;
    for (const detail::Simplex s : log.trialRemovals ())
      removed.emplace_back (s.dim, s.id);
    std::sort (removed.begin (), removed.end ());
    EXPECT_TRUE (std::adjacent_find (removed.begin (), removed.end ()) == removed.end ()) << "a removal logged twice";
    const auto after = membershipAndCounts (y);
    log.rollbackTrial (y);
    EXPECT_EQ (membershipAndCounts (y), before) << "the trial was not put back";
    return std::make_pair (after, removed);
  };
  const auto one_thread = run (5);
  EXPECT_GT (one_thread.second.size (), 20000u) << "too short a retraction to go on all threads";
  for (int attempt = 0; attempt < 3; ++attempt)
    EXPECT_EQ (run (0), one_thread) << "attempt " << attempt;
}

/** Every W triangle with a tetrahedron of X behind it has that tetrahedron on its negative side. */
void
expectOrientedAwayFromX (const std::vector<Point3>& points, const WrapResult& r)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto point = [&] (PointIndex i) { return K::Point_3 (points[i][0], points[i][1], points[i][2]); };
  const auto apex = apexesOfXTriangles (r);
  std::size_t checked = 0;
  for (const auto& t : r.surface.triangles)
  {
    Tuple key (t.begin (), t.end ());
    std::sort (key.begin (), key.end ());
    auto it = apex.find (key);
    if (it == apex.end ())
      continue; // a sheet
    EXPECT_EQ (CGAL::orientation (point (t[0]), point (t[1]), point (t[2]), point (it->second)), CGAL::NEGATIVE);
    ++checked;
  }
  EXPECT_GT (checked, 0u);
}

TEST (Retraction, XIsContractibleAndWIsItsBoundary)
{
  for (std::size_t n : {200u, 1000u, 3000u})
    for (unsigned seed = 1; seed <= 2; ++seed)
      for (const auto& points : shapes (n, seed))
      {
        SCOPED_TRACE ("n " + std::to_string (n) + " seed " + std::to_string (seed));
        const WrapResult r = computeWrap (points, rawOutput ());
        expectWrapInvariants (r);
        for (const auto& t : r.surface.triangles)
          for (PointIndex v : t)
            ASSERT_LT (v, points.size ());
        expectOrientedAwayFromX (points, r);
      }
}

} // namespace
} // namespace pcl_wrap::test

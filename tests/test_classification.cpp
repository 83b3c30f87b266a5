// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// Classification (docs/design.md §2-§4): the engine's exact predicates against an independent
// rational construction, and the invariants of the flow relation on many random inputs.
#include "support/exact_reference.h"
#include "support/flow_checks.h"
#include "support/pipeline.h"
#include "support/samplers.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <queue>
#include <string>

namespace pcl_wrap::test
{
namespace
{

using detail::Simplex;
using detail::SimplexId;

struct Sample
{
  std::string name;
  std::function<std::vector<Point3> (std::size_t, unsigned)> make;
};

const std::vector<Sample>&
samples ()
{
  static const std::vector<Sample> all = {
      {"cube", [] (std::size_t n, unsigned s) { return cubeSample (n, s); }},
      {"sphere", [] (std::size_t n, unsigned s) { return sphereSample (n, s, 0.05); }},
      {"torus", [] (std::size_t n, unsigned s) { return torusSample (n, s); }}};
  return all;
}

std::vector<std::uint32_t>
localVertices (const Pipeline& p, Simplex s)
{
  return {p.complex.vertices (s.dim, s.id), p.complex.vertices (s.dim, s.id) + s.dim + 1};
}

void
expectExactClasses (const Pipeline& p)
{
  std::size_t checked = 0;
  forEachSimplex (p, [&] (Simplex s) {
    const ExactClass e = classifyExactly (p.points, p.weights, localVertices (p, s), p.dimension ());
    ASSERT_FALSE (e.degenerate) << "random input hit an exact tie";
    ASSERT_EQ (p.classification.of (s), e.cls) << "simplex " << s.dim << ":" << s.id;
    ASSERT_EQ (p.classification.lowest_successor[s.dim][s.id], e.lowest_successor_mask);
    ++checked;
  });
  EXPECT_GT (checked, 10 * p.points.size ());
}

TEST (Classification, MatchesExactRationalReference)
{
  for (const Sample& sample : samples ())
    for (unsigned seed = 1; seed <= 6; ++seed)
    {
      SCOPED_TRACE (sample.name + " seed " + std::to_string (seed));
      const Pipeline p (sample.make (40, seed));
      ASSERT_EQ (p.dimension (), 3);
      expectExactClasses (p);
    }
  // The torus samples of test_wrap_shapes, whose sheets are thereby known to be right.
  for (unsigned seed = 1; seed <= 3; ++seed)
  {
    SCOPED_TRACE ("torus 200 seed " + std::to_string (seed));
    expectExactClasses (Pipeline (torusSample (200, seed)));
  }
}

TEST (Classification, FlowRelationInvariants)
{
  for (const Sample& sample : samples ())
    for (std::size_t n : {200u, 1000u, 2500u})
      for (unsigned seed = 1; seed <= 3; ++seed)
      {
        SCOPED_TRACE (sample.name + " n " + std::to_string (n) + " seed " + std::to_string (seed));
        const Pipeline pipeline (sample.make (n, seed));
        expectFlowInvariants (pipeline);
        expectCofaceCounts (pipeline);
      }
}

/** Claim 9 made checkable: with R^2 the squared radius of the smallest *empty* orthosphere (the
  * size of a centered or confident simplex, the size of its predecessor for an equivocal one),
  * every coface of an equivocal v other than the faces of its predecessor has a larger R^2. So
  * the pair (R^2, -dim) strictly increases along the flow, which is therefore acyclic; the test
  * also runs a topological sort over the relation to see it directly. */
TEST (Classification, FlowRelationIsAcyclic)
{
  for (const Sample& sample : samples ())
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
      SCOPED_TRACE (sample.name + " seed " + std::to_string (seed));
      const Pipeline p (sample.make (300, seed));
      const auto pred = predecessorsBySuccession (p);
      std::map<std::pair<int, SimplexId>, Rational> r2;
      forEachSimplex (p, [&] (Simplex s) {
        const auto& owner = p.classification.of (s) == SimplexClass::equivocal ? pred.at ({s.dim, s.id}).front () : s;
        r2[{s.dim, s.id}] = smallestOrthosphere (p.points, p.weights, localVertices (p, owner)).squared_radius;
      });
      // The relation: confident -> its successors; equivocal -> cofaces outside its predecessor.
      std::map<std::pair<int, SimplexId>, std::vector<std::pair<int, SimplexId>>> next;
      forEachSimplex (p, [&] (Simplex xi) {
        for (unsigned m = 1; m < detail::fullMask (xi.dim); ++m)
        {
          const Simplex f = p.complex.face (xi.dim, xi.id, m);
          const SimplexClass fc = p.classification.of (f);
          if (fc == SimplexClass::equivocal)
          {
            const Tuple owner = p.tuple (pred.at ({f.dim, f.id}).front ());
            const Tuple x = p.tuple (xi);
            if (std::includes (owner.begin (), owner.end (), x.begin (), x.end ()))
            {
              ASSERT_EQ (r2.at ({f.dim, f.id}), r2.at ({xi.dim, xi.id}))
                  << "a successor shares its predecessor's sphere";
              next[{xi.dim, xi.id}].push_back ({f.dim, f.id}); // confident xi -> successor f
            }
            else
            {
              ASSERT_GT (r2.at ({xi.dim, xi.id}), r2.at ({f.dim, f.id}))
                  << "flow out of an equivocal simplex must rise";
              next[{f.dim, f.id}].push_back ({xi.dim, xi.id});
            }
          }
        }
      });
      std::map<std::pair<int, SimplexId>, int> indegree;
      for (const auto& [from, to] : next)
        for (const auto& t : to)
          ++indegree[t];
      std::queue<std::pair<int, SimplexId>> ready;
      std::size_t nodes = 0, sorted = 0;
      forEachSimplex (p, [&] (Simplex s) {
        ++nodes;
        if (!indegree.count ({s.dim, s.id}))
          ready.push ({s.dim, s.id});
      });
      while (!ready.empty ())
      {
        const auto s = ready.front ();
        ready.pop ();
        ++sorted;
        if (next.count (s))
          for (const auto& t : next.at (s))
            if (--indegree[t] == 0)
              ready.push (t);
      }
      EXPECT_EQ (sorted, nodes) << "the flow relation has a cycle";
    }
}

TEST (Classification, UnweightedVerticesAreSinksAndEdgesNeverConfident)
{
  const Pipeline p (cubeSample (500, 7));
  for (SimplexId v = 0; v < p.complex.size (0); ++v)
    EXPECT_EQ (p.classification.of ({0, v}), SimplexClass::centered);
  for (SimplexId e = 0; e < p.complex.size (1); ++e)
    EXPECT_NE (p.classification.of ({1, e}), SimplexClass::confident);
}

} // namespace
} // namespace pcl_wrap::test

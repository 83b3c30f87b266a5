// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "naive_retraction.h"

#include "exact_reference.h"
#include "pipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

namespace pcl_wrap::test
{
namespace
{

using Tuple = std::vector<std::uint32_t>;

bool
isSubset (const Tuple& a, const Tuple& b)
{
  return std::includes (b.begin (), b.end (), a.begin (), a.end ());
}

} // namespace

std::vector<Tuple>
naiveRetraction (const std::vector<NaiveSimplex>& del, unsigned seed, const std::vector<Tuple>& deletions)
{
  std::map<Tuple, const NaiveSimplex*> by_vertices;
  for (const auto& s : del)
    by_vertices[s.vertices] = &s;
  std::set<Tuple> y;
  for (const auto& s : del)
    y.insert (s.vertices);
  std::mt19937 random (seed);

  std::size_t next_deletion = 0;
  for (;;)
  {
    // Every collapsible pair (LS(tau), tau) of the current Y.
    std::vector<const NaiveSimplex*> collapsible;
    for (const auto& tau : del)
    {
      if (tau.cls != SimplexClass::confident || !y.count (tau.vertices) || !y.count (tau.lowest_successor))
        continue;
      if (by_vertices.at (tau.lowest_successor)->cls != SimplexClass::equivocal)
        continue;
      const bool free = std::all_of (y.begin (), y.end (), [&] (const Tuple& xi) {
        return !isSubset (tau.lowest_successor, xi) || isSubset (xi, tau.vertices);
      });
      if (free)
        collapsible.push_back (&tau);
    }
    if (!collapsible.empty ())
    {
      const NaiveSimplex& tau = *collapsible[random () % collapsible.size ()];
      for (auto it = y.begin (); it != y.end ();)
        if (isSubset (tau.lowest_successor, *it) && isSubset (*it, tau.vertices))
          it = y.erase (it);
        else
          ++it;
      continue;
    }
    // Retracted: delete the next sink that is still there and principal; stop when none is left.
    bool deleted = false;
    while (!deleted && next_deletion < deletions.size ())
    {
      const Tuple& sink = deletions[next_deletion++];
      const bool principal = y.count (sink) && std::none_of (y.begin (), y.end (), [&] (const Tuple& xi) {
        return xi != sink && isSubset (sink, xi);
      });
      if (principal)
      {
        y.erase (sink);
        deleted = true;
      }
    }
    if (!deleted)
      break;
  }
  return {y.begin (), y.end ()};
}

std::vector<NaiveSimplex>
naiveComplexWithExactClasses (const Pipeline& p)
{
  std::vector<NaiveSimplex> del;
  for (int k = 0; k <= p.dimension (); ++k)
    for (detail::SimplexId s = 0; s < p.complex.size (k); ++s)
    {
      const std::uint32_t* v = p.complex.vertices (k, s);
      const ExactClass e = classifyExactly (p.points, p.weights, {v, v + k + 1}, p.dimension ());
      EXPECT_FALSE (e.degenerate) << "the reference met a tie";
      NaiveSimplex n{p.tuple ({k, s}), e.cls, {}};
      for (int i = 0; i <= k; ++i)
        if (e.lowest_successor_mask & (1u << i))
          n.lowest_successor.push_back (v[i]);
      std::sort (n.lowest_successor.begin (), n.lowest_successor.end ());
      del.push_back (std::move (n));
    }
  return del;
}

} // namespace pcl_wrap::test

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "naive_retraction.h"

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
naiveRetraction (const std::vector<NaiveSimplex>& del, unsigned seed)
{
  std::map<Tuple, const NaiveSimplex*> by_vertices;
  for (const auto& s : del)
    by_vertices[s.vertices] = &s;
  std::set<Tuple> y;
  for (const auto& s : del)
    y.insert (s.vertices);
  std::mt19937 random (seed);

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
    if (collapsible.empty ())
      break;
    const NaiveSimplex& tau = *collapsible[random () % collapsible.size ()];
    for (auto it = y.begin (); it != y.end ();)
      if (isSubset (tau.lowest_successor, *it) && isSubset (*it, tau.vertices))
        it = y.erase (it);
      else
        ++it;
  }
  return {y.begin (), y.end ()};
}

} // namespace pcl_wrap::test

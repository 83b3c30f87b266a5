// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "flow_checks.h"

#include <gtest/gtest.h>

namespace pcl_wrap::test
{

using detail::Simplex;
using detail::SimplexId;

std::map<std::pair<int, SimplexId>, std::vector<Simplex>>
predecessorsBySuccession (const Pipeline& p)
{
  std::map<std::pair<int, SimplexId>, std::vector<Simplex>> pred;
  forEachSimplex (p, [&] (Simplex tau) {
    if (p.classification.of (tau) != SimplexClass::confident)
      return;
    const unsigned low = p.classification.lowest_successor[tau.dim][tau.id];
    for (unsigned m = low; m < detail::fullMask (tau.dim); m = (m + 1) | low)
    {
      const Simplex successor = p.complex.face (tau.dim, tau.id, m);
      pred[{successor.dim, successor.id}].push_back (tau);
    }
  });
  return pred;
}


void
expectFlowInvariants (const Pipeline& p)
{
  const auto& c = p.classification;
  forEachSimplex (p, [&] (Simplex tau) {
    if (c.of (tau) != SimplexClass::confident)
      return;
    const unsigned low = c.lowest_successor[tau.dim][tau.id];
    ASSERT_NE (low, 0u);
    ASSERT_NE (low, detail::fullMask (tau.dim));
    for (unsigned m = low; m < detail::fullMask (tau.dim); m = (m + 1) | low)
      ASSERT_EQ (c.of (p.complex.face (tau.dim, tau.id, m)), SimplexClass::equivocal);
  });
  const auto pred = predecessorsBySuccession (p);
  forEachSimplex (p, [&] (Simplex v) {
    if (c.of (v) != SimplexClass::equivocal)
      return;
    auto it = pred.find ({v.dim, v.id});
    ASSERT_TRUE (it != pred.end ()) << "equivocal simplex without predecessor";
    ASSERT_EQ (it->second.size (), 1u) << "equivocal simplex with several predecessors";
  });
  EXPECT_EQ (c.extra_predecessors, 0u);
}

void
expectCofaceCounts (const Pipeline& p)
{
  std::map<Tuple, std::uint32_t> facets_named;
  forEachSimplex (p, [&] (Simplex s) {
    const Tuple t = p.tuple (s);
    for (std::size_t drop = 0; s.dim > 0 && drop < t.size (); ++drop)
    {
      Tuple facet = t;
      facet.erase (facet.begin () + drop);
      ++facets_named[facet];
    }
  });
  for (int k = 0; k < 3; ++k)
  {
    const auto& counts = p.complex.cofaceCounts (k);
    ASSERT_EQ (counts.size (), p.complex.size (k)) << "dimension " << k;
    for (detail::SimplexId s = 0; s < counts.size (); ++s)
    {
      const auto it = facets_named.find (p.tuple ({k, s}));
      ASSERT_EQ (counts[s], it == facets_named.end () ? 0u : it->second) << "dimension " << k << " simplex " << s;
    }
  }
}

} // namespace pcl_wrap::test

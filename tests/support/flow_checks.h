// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// The invariants of the flow relation (docs/design.md §4) on a classified complex.
#include "pipeline.h"

#include <map>
#include <utility>
#include <vector>

namespace pcl_wrap::test
{

/** Calls f(simplex) for every simplex of the complex. */
template <class F>
void
forEachSimplex (const Pipeline& p, const F& f)
{
  for (int k = 0; k <= p.dimension (); ++k)
    for (detail::SimplexId s = 0; s < p.complex.size (k); ++s)
      f (detail::Simplex{k, s});
}

/** The confident simplices each simplex succeeds, found by scanning every confident simplex's
  * successors (the proper faces containing its lowest successor). */
std::map<std::pair<int, detail::SimplexId>, std::vector<detail::Simplex>>
predecessorsBySuccession (const Pipeline& p);

/** Asserts (gtest): every confident simplex has a proper, non-empty lowest successor, all its
  * successors are equivocal, and every equivocal simplex succeeds exactly one confident simplex
  * (Claim 8). */
void
expectFlowInvariants (const Pipeline& p);

/** Asserts (gtest): the complex's coface counts are those of its simplices' vertex tuples: each
  * simplex of dimension k < 3 lies in as many (k+1)-simplices as name it among their facets. */
void
expectCofaceCounts (const Pipeline& p);

} // namespace pcl_wrap::test

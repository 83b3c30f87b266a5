// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "front_checks.h"

#include "wrap/front_deletion.h"
#include "wrap/removal_log.h"
#include "wrap/retraction.h"
#include "wrap/wrap_filtration.h"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace pcl_wrap::test
{

std::size_t
expectFrontDeletionIsAFixpoint (const Pipeline& p, double delta)
{
  using detail::Simplex;
  detail::WrapFiltration order;
  detail::orderSinks (p.complex, p.classification, p.points, p.weights, order, delta);
  detail::Subcomplex y (p.complex);
  detail::Retraction (y, p.classification).retract ();
  detail::deleteExposedSinks (y, p.classification, order, delta);

  // W of the final Y: a triangle with fewer than two tetrahedra, an edge with no triangle, a
  // vertex with no edge.
  std::array<std::vector<std::uint8_t>, 3> on_w;
  for (int k = 0; k < 3; ++k)
    for (detail::SimplexId s = 0; s < p.complex.size (k); ++s)
      on_w[k].push_back (y.contains ({k, s}) && y.cofaceCount ({k, s}) < (k == 2 ? 2u : 1u));
  // The trial as docs/design.md §6 defines it: the sink, then the sinks above delta it leaves
  // principal, largest first, until what was removed touches W or none is left.
  std::map<std::pair<int, detail::SimplexId>, std::size_t> rank;
  for (std::size_t j = 0; j < order.sinks.size () && order.sink_sizes[j] > delta; ++j)
    rank[{order.sinks[j].dim, order.sinks[j].id}] = j;
  detail::RemovalLog log (p.complex);
  detail::Retraction retraction (y, p.classification, &log);
  std::size_t tried = 0;
  for (const auto& [sink, j] : rank)
  {
    log.beginTrial ();
    std::set<std::size_t> pending = {j};
    bool reached = false;
    while (!pending.empty () && !reached)
    {
      const Simplex s = order.sinks[*pending.begin ()];
      pending.erase (pending.begin ());
      if (!retraction.deletePrincipal (s))
        continue;
      retraction.retractFreed ();
      for (const Simplex xi : log.trialRemovals ())
      {
        reached = reached || (xi.dim < 3 && on_w[xi.dim][xi.id]);
        for (int i = 0; i <= xi.dim && xi.dim > 0; ++i)
        {
          const Simplex f = p.complex.facet (xi.dim, xi.id, i);
          const auto it = rank.find ({f.dim, f.id});
          if (it != rank.end () && y.principal (f))
            pending.insert (it->second);
        }
      }
    }
    tried += !log.trialRemovals ().empty ();
    if (reached)
      ADD_FAILURE () << "the sink of rank " << j << " was left, but its trial reaches W";
    log.rollbackTrial (y);
  }
  return tried;
}

} // namespace pcl_wrap::test

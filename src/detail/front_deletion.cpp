// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "front_deletion.h"

#include "removal_log.h"
#include "retraction.h"

#include <array>
#include <set>
#include <unordered_map>

namespace pcl_wrap::detail
{
namespace
{

/** Watches a trial's removals for one that was on the front (W, or the part of it on flagged
  * vertices) just before the trial: in a 3-dimensional
  * complex, a triangle with fewer than two tetrahedra of X, an edge with no triangle, a vertex
  * with no edge (in lower dimensions everything is on W). A removed simplex's cofaces leave in
  * the same step or earlier (Y stays a complex), so counting them among the removals tells how
  * many it had, and once a step is over only the new removals need a look. */
class SurfaceWatch
{
public:
  SurfaceWatch (const SimplicialComplex& complex, const std::vector<std::uint8_t>& in_front)
    : complex_ (complex), in_front_ (in_front)
  {}

  /** Looks at the removals it has not seen; true when one of them was on the front. */
  bool reached (const std::vector<Simplex>& removed)
  {
    if (complex_.dimension () < 3)
    {
      for (; seen_ < removed.size (); ++seen_)
        if (inRegion (removed[seen_]))
          return true;
      return false;
    }
    const std::size_t first = seen_;
    for (; seen_ < removed.size (); ++seen_)
      for (int i = 0; i <= removed[seen_].dim && removed[seen_].dim > 0; ++i)
        ++cofaces_before_[key (complex_.facet (removed[seen_].dim, removed[seen_].id, i))];
    for (std::size_t k = first; k < removed.size (); ++k)
    {
      const Simplex xi = removed[k];
      if (xi.dim == 3 || !inRegion (xi))
        continue;
      const auto it = cofaces_before_.find (key (xi));
      const std::uint32_t before = it == cofaces_before_.end () ? 0 : it->second;
      if (before < (xi.dim == 2 ? 2u : 1u))
        return true;
    }
    return false;
  }

private:
  bool inRegion (Simplex s) const
  {
    if (in_front_.empty ())
      return true;
    for (int i = 0; i <= s.dim; ++i)
      if (!in_front_[complex_.vertex (s.dim, s.id, i)])
        return false;
    return true;
  }

  static std::uint64_t key (Simplex s) { return (std::uint64_t (s.dim) << 32) | s.id; }

  const SimplicialComplex& complex_;
  const std::vector<std::uint8_t>& in_front_;
  std::unordered_map<std::uint64_t, std::uint32_t> cofaces_before_;
  std::size_t seen_ = 0;
};

} // namespace

FrontDeletion
deleteExposedSinks (Subcomplex& y, const Classification& classification, const WrapFiltration& order, double delta,
                    const std::vector<std::uint8_t>& in_front, std::uint64_t order_seed)
{
  const SimplicialComplex& complex = y.complex ();
  RemovalLog log (complex);
  Retraction retraction (y, classification, &log);
  // The rank of every sink larger than delta, to find those a trial uncovers.
  constexpr std::uint32_t NOT_CANDIDATE = ~std::uint32_t (0);
  std::array<std::vector<std::uint32_t>, 4> rank;
  for (int k = 0; k <= 3; ++k)
    rank[k].assign (complex.size (k), NOT_CANDIDATE);
  std::size_t candidates = 0;
  while (candidates < order.sinks.size () && order.sink_sizes[candidates] > delta)
  {
    rank[order.sinks[candidates].dim][order.sinks[candidates].id] = static_cast<std::uint32_t> (candidates);
    ++candidates;
  }

  FrontDeletion result;
  for (bool progress = true; progress;)
  {
    progress = false;
    for (std::size_t j = 0; j < candidates; ++j)
    {
      if (!y.principal (order.sinks[j]))
        continue;
      // A trial deletes the sink, then, while its basin has not reached the surface, the larger-
      // than-delta sinks it made principal (its cosinks), largest first. All or nothing.
      log.beginTrial ();
      std::set<std::uint32_t> pending = {static_cast<std::uint32_t> (j)};
      SurfaceWatch surface (complex, in_front);
      std::size_t scanned = 0, deleted = 0;
      bool reached = false;
      while (!pending.empty () && !reached)
      {
        const Simplex sink = order.sinks[*pending.begin ()];
        pending.erase (pending.begin ());
        if (!retraction.deletePrincipal (sink))
          continue;
        ++deleted;
        retraction.retractFreed (order_seed);
        reached = surface.reached (log.trialRemovals ());
        for (; scanned < log.trialRemovals ().size (); ++scanned)
        {
          const Simplex xi = log.trialRemovals ()[scanned];
          for (unsigned mask = 1; mask < fullMask (xi.dim); ++mask)
          {
            const Simplex f = complex.face (xi.dim, xi.id, mask);
            if (rank[f.dim][f.id] != NOT_CANDIDATE && y.principal (f))
              pending.insert (rank[f.dim][f.id]);
          }
        }
      }
      if (reached)
      {
        log.commitTrial ();
        result.deleted += deleted;
        progress = true;
      }
      else
        log.rollbackTrial (y);
    }
  }
  for (std::size_t j = 0; j < candidates; ++j)
    if (y.contains (order.sinks[j]))
      ++(y.principal (order.sinks[j]) ? result.enclosed : result.not_principal);
  return result;
}

} // namespace pcl_wrap::detail

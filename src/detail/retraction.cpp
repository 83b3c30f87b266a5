// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "retraction.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <random>

namespace pcl_wrap::detail
{

Retraction::Retraction (Subcomplex& y, const Classification& classification, RemovalLog* log)
  : y_ (y), complex_ (y.complex ()), classification_ (classification), log_ (log)
{}

bool
Retraction::collapsible (Simplex v) const
{
  const Simplex tau = classification_.predecessor[v.dim][v.id];
  if (tau.id == NO_SIMPLEX || !y_.contains (v) || !y_.contains (tau) || classification_.of (v) != SimplexClass::equivocal)
    return false;
  // v is free with tau its largest coface iff every coface of v in Y is a face of tau. The k - l
  // faces of tau one dimension above v are in Y (Y is a complex, tau is in it), and any other
  // coface xi of v has a vertex q outside tau, so v + q is one more coface one dimension up.
  // Counting those suffices.
  return y_.cofaceCount (v) == static_cast<std::uint32_t> (tau.dim - v.dim);
}

template <bool CONCURRENT>
void
Retraction::remove (Simplex xi, unsigned removed_mask, Simplex tau, unsigned kept_below, std::vector<Simplex>& work)
{
  y_.take<CONCURRENT> (xi);
  if (!CONCURRENT && log_)
    log_->record (xi);
  if (xi.dim == 0)
    return;
  // The facets of xi, named by masks within tau; those containing kept_below go too.
  for (unsigned drop = removed_mask; drop != 0; drop &= drop - 1)
  {
    const unsigned facet = removed_mask & ~(drop & -drop);
    const Simplex f = complex_.face (tau.dim, tau.id, facet);
    y_.loseCoface<CONCURRENT> (f);
    if ((facet & kept_below) != kept_below)
      work.push_back (f); // stays, and may have become free
  }
}

template <bool CONCURRENT>
void
Retraction::collapse (Simplex tau, std::vector<Simplex>& work)
{
  const unsigned low = classification_.lowest_successor[tau.dim][tau.id];
  for (unsigned removed = low; removed <= fullMask (tau.dim); removed = (removed + 1) | low)
    remove<CONCURRENT> (complex_.face (tau.dim, tau.id, removed), removed, tau, low, work);
}

std::size_t
Retraction::retractInParallel ()
{
  // Why threads may collapse at once: the intervals [v, tau] of the flow are disjoint, so a
  // collapse removes only its own interval; the faces of tau above v are in that interval, so
  // no other thread removes them, and v's coface count reaches tau.dim - v.dim exactly when
  // every other coface is gone, for good (counts only fall). A thread that sees that may
  // collapse; taking tau out first lets one thread only do so. The thread whose removal makes
  // the last decrement sees the final count (atomic read-modify-write), so no pair that becomes
  // free is missed; and the result does not depend on the order (docs/design.md §5).
  std::atomic<std::size_t> collapses{0};
  for (int k = 0; k < complex_.dimension (); ++k)
    tbb::parallel_for (tbb::blocked_range<SimplexId> (0, static_cast<SimplexId> (complex_.size (k)), 4096),
                       [&] (const tbb::blocked_range<SimplexId>& range) {
                         std::vector<Simplex> work;
                         std::size_t done = 0;
                         for (SimplexId s = range.begin (); s != range.end (); ++s)
                         {
                           if (!hasPredecessor ({k, s}))
                             continue;
                           work.push_back ({k, s});
                           while (!work.empty ())
                           {
                             const Simplex v = work.back ();
                             work.pop_back ();
                             if (!collapsible (v))
                               continue;
                             const Simplex tau = classification_.predecessor[v.dim][v.id];
                             if (!y_.takeFirst (tau))
                               continue; // another thread collapses this pair
                             collapse<true> (tau, work);
                             ++done;
                           }
                         }
                         collapses += done;
                       });
  return collapses;
}

std::size_t
Retraction::retract (std::uint64_t order_seed)
{
  if (order_seed == 0 && !(log_ && log_->recording ()) && work_.empty ())
    return retractInParallel ();
  for (int k = 0; k < complex_.dimension (); ++k)
    for (SimplexId s = 0; s < complex_.size (k); ++s)
      if (hasPredecessor ({k, s}))
        work_.push_back ({k, s});
  return retractFreed (order_seed);
}

bool
Retraction::deletePrincipal (Simplex s)
{
  // Any coface of s contains a coface one dimension up: none of those, no coface at all.
  if (!y_.principal (s))
    return false;
  remove<false> (s, fullMask (s.dim), s, fullMask (s.dim), work_);
  return true;
}

std::size_t
Retraction::retractFreed (std::uint64_t order_seed)
{
  std::mt19937_64 random (order_seed);
  std::size_t collapses = 0;
  while (!work_.empty ())
  {
    if (order_seed != 0)
      std::swap (work_[random () % work_.size ()], work_.back ());
    const Simplex v = work_.back ();
    work_.pop_back ();
    if (collapsible (v))
    {
      collapse<false> (classification_.predecessor[v.dim][v.id], work_);
      ++collapses;
    }
  }
  return collapses;
}

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "retraction.h"
#include "portable.h"

#include "parallel_for_each.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>

#include <random>

namespace pcl_wrap::detail
{
Retraction::Retraction (const SimplicialComplex& complex, const Classification& classification)
  : Retraction (complex, classification, {complex.cofaceCounts (0), complex.cofaceCounts (1), complex.cofaceCounts (2)})
{}

Retraction::Retraction (const SimplicialComplex& complex, const Classification& classification,
                        std::array<FilledInParallel<std::uint32_t>, 3> coface_counts)
  : complex_ (complex), classification_ (classification), counts_ (std::move (coface_counts))
{
  // All of Del S is in Y (omega never counts), so its coface counts are the complex's; when they
  // come empty (the complex handed its own over to another retraction), they are counted here.
  for (int k = 0; k <= 3; ++k)
  {
    alive_[k].resize (complex.size (k));
    parallelForEach (complex.size (k), [&] (std::size_t s) { alive_[k][s] = 1; });
  }
  if (counts_[0].size () != complex.size (0))
    countCofaces ();
}

Retraction::Retraction (const SimplicialComplex& complex, const Classification& classification,
                        const std::array<std::vector<std::uint8_t>, 4>& in_y)
  : complex_ (complex), classification_ (classification)
{
  for (int k = 0; k <= 3; ++k)
    alive_[k].assign (in_y[k].begin (), in_y[k].end ());
  countCofaces ();
}

void
Retraction::countCofaces ()
{
  for (int k = 0; k < 3; ++k)
    counts_[k].assign (complex_.size (k), 0);
  // In parallel: a facet is shared, so its count is bumped atomically (relaxed: only the
  // totals matter, read after the loop).
  for (int m = 1; m <= complex_.dimension (); ++m)
    parallelForEach (complex_.size (m), [&] (std::size_t id) {
      const auto s = static_cast<SimplexId> (id);
      if (alive_[m][s])
        for (int i = 0; i <= m; ++i)
          relaxedFetchAdd (&counts_[m - 1][complex_.facet (m, s, i).id], 1u);
    });
}

bool
Retraction::collapsible (Simplex v) const
{
  const Simplex tau = classification_.predecessor[v.dim][v.id];
  if (tau.id == NO_SIMPLEX || !inY (v) || !inY (tau) || classification_.of (v) != SimplexClass::equivocal)
    return false;
  // v is free with tau its largest coface iff every coface of v in Y is a face of tau. The k - l
  // faces of tau one dimension above v are in Y (Y is a complex, tau is in it), and any other
  // coface xi of v has a vertex q outside tau, so v + q is one more coface one dimension up.
  // Counting those suffices.
  return cofacesInY (v) == static_cast<std::uint32_t> (tau.dim - v.dim);
}

template <bool CONCURRENT>
void
Retraction::remove (Simplex xi, unsigned removed_mask, Simplex tau, unsigned kept_below, std::vector<Simplex>& work)
{
  relaxedStore (&alive_[xi.dim][xi.id], std::uint8_t (0));
  if (stamp_ != 0)
    stamps_[xi.dim][xi.id] = stamp_;
  if (in_trial_)
    trial_.push_back (xi);
  if (xi.dim == 0)
    return;
  // The facets of xi, named by masks within tau; those containing kept_below go too.
  for (unsigned drop = removed_mask; drop != 0; drop &= drop - 1)
  {
    const unsigned facet = removed_mask & ~(drop & -drop);
    const Simplex f = complex_.face (tau.dim, tau.id, facet);
    if (CONCURRENT)
      relaxedFetchSub (&counts_[f.dim][f.id], 1u);
    else
      --counts_[f.dim][f.id];
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
  // collapse; the exchange on tau's flag lets one thread only do so. The thread whose removal
  // makes the last decrement sees the final count (atomic read-modify-write), so no pair that
  // becomes free is missed; and the result does not depend on the order (docs/design.md §5).
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
                             std::uint8_t alive = 1;
                             if (!relaxedCompareExchange (&alive_[tau.dim][tau.id], alive, std::uint8_t (0)))
                               continue; // another thread collapses this pair
                             collapse<true> (tau, work);
                             ++done;
                           }
                         }
                         collapses += done;
                       });
  return collapses;
}

bool
Retraction::deletePrincipal (Simplex s)
{
  // Any coface of s contains a coface one dimension up: none of those, no coface at all.
  if (!inY (s) || cofacesInY (s) != 0)
    return false;
  remove<false> (s, fullMask (s.dim), s, fullMask (s.dim), work_);
  return true;
}

void
Retraction::rollbackTrial ()
{
  for (auto it = trial_.rbegin (); it != trial_.rend (); ++it)
  {
    const Simplex xi = *it;
    alive_[xi.dim][xi.id] = 1;
    if (!stamps_[xi.dim].empty ())
      stamps_[xi.dim][xi.id] = 0;
    for (int i = 0; i <= xi.dim && xi.dim > 0; ++i)
      ++counts_[xi.dim - 1][complex_.facet (xi.dim, xi.id, i).id];
  }
  trial_.clear ();
  in_trial_ = false;
  work_.clear ();
}

void
Retraction::stampRemovals (std::uint32_t stamp)
{
  if (stamps_[0].empty ())
    for (int k = 0; k <= 3; ++k)
      stamps_[k].assign (complex_.size (k), 0);
  stamp_ = stamp;
}

std::size_t
Retraction::retract (std::uint64_t order_seed)
{
  // The first retraction starts from every equivocal simplex that is some lowest successor;
  // later ones (after deletions) from the work the deletions queued.
  if (!seeded_ && order_seed == 0 && !in_trial_ && stamp_ == 0)
  {
    seeded_ = true;
    return retractInParallel ();
  }
  if (!seeded_)
    for (int k = 0; k < complex_.dimension (); ++k)
      for (SimplexId s = 0; s < complex_.size (k); ++s)
        if (hasPredecessor ({k, s}))
          work_.push_back ({k, s});
  seeded_ = true;

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

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap/retraction.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_for_each.h>
#include <tbb/task_arena.h>

#include <algorithm>
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
  return freePair (y_, classification_, v);
}

template <bool CONCURRENT>
void
Retraction::remove (Simplex xi, unsigned removed_mask, Simplex tau, unsigned kept_below, std::vector<Simplex>& work,
                    std::vector<Simplex>* removed)
{
  y_.take<CONCURRENT> (xi);
  if (log_ && CONCURRENT)
    removed->push_back (xi); // handed to the log in batches
  else if (log_)
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
Retraction::collapse (Simplex tau, std::vector<Simplex>& work, std::vector<Simplex>* removed)
{
  const unsigned low = classification_.lowest_successor[tau.dim][tau.id];
  for (unsigned mask = low; mask <= fullMask (tau.dim); mask = (mask + 1) | low)
    remove<CONCURRENT> (complex_.face (tau.dim, tau.id, mask), mask, tau, low, work, removed);
}

template <class Share>
std::size_t
Retraction::collapseConcurrently (std::vector<Simplex>& work, std::vector<Simplex>& removed, const Share& share)
{
  std::size_t done = 0;
  while (!work.empty ())
  {
    const Simplex v = work.back ();
    work.pop_back ();
    if (!collapsible (v))
      continue;
    const Simplex tau = classification_.predecessor[v.dim][v.id];
    if (!y_.takeFirst (tau))
      continue; // another thread collapses this pair
    collapse<true> (tau, work, &removed);
    ++done;
    share (work);
    if (removed.size () >= LOGGED_TOGETHER)
      handToLog (removed);
  }
  return done;
}

void
Retraction::handToLog (std::vector<Simplex>& removed)
{
  if (log_ && !removed.empty ())
    log_->recordConcurrently (removed);
  removed.clear ();
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
                         std::vector<Simplex> work, removed;
                         std::size_t done = 0;
                         for (SimplexId s = range.begin (); s != range.end (); ++s)
                           if (hasPredecessor ({k, s}))
                           {
                             work.push_back ({k, s});
                             done += collapseConcurrently (work, removed, [] (std::vector<Simplex>&) {});
                           }
                         handToLog (removed);
                         collapses += done;
                       });
  return collapses;
}

std::size_t
Retraction::retractFreedInParallel ()
{
  // As in retractInParallel(), but from the queued work only, which may be one basin: a thread
  // that sees another without work hands it the older half of its own.
  using Chunk = std::vector<Simplex>;
  std::vector<Chunk> chunks;
  for (std::size_t i = 0; i < work_.size (); i += SHARED_WORK)
    chunks.emplace_back (work_.begin () + i, work_.begin () + std::min (work_.size (), i + SHARED_WORK));
  work_.clear ();
  const int threads = tbb::this_task_arena::max_concurrency ();
  std::atomic<int> busy{static_cast<int> (chunks.size ())}; // chunks running or waiting
  std::atomic<std::size_t> collapses{0};
  tbb::parallel_for_each (chunks.begin (), chunks.end (), [&] (const Chunk& chunk, tbb::feeder<Chunk>& feeder) {
    Chunk work = chunk, removed;
    collapses += collapseConcurrently (work, removed, [&] (Chunk& own) {
      if (own.size () < 2 || busy.load (std::memory_order_relaxed) >= threads)
        return;
      ++busy;
      const auto half = own.begin () + static_cast<std::ptrdiff_t> (own.size () / 2);
      feeder.add (Chunk (own.begin (), half));
      own.erase (own.begin (), half);
    });
    handToLog (removed);
    --busy;
  });
  return collapses;
}

std::size_t
Retraction::retract (std::uint64_t order_seed)
{
  if (order_seed == 0 && work_.empty ())
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
  remove<false> (s, fullMask (s.dim), s, fullMask (s.dim), work_, nullptr);
  return true;
}

std::size_t
Retraction::retractFreed (std::uint64_t order_seed)
{
  std::mt19937_64 random (order_seed);
  std::size_t collapses = 0;
  while (!work_.empty ())
  {
    if (order_seed == 0 && collapses == ALONE)
      return collapses + retractFreedInParallel ();
    if (order_seed != 0)
      std::swap (work_[random () % work_.size ()], work_.back ());
    const Simplex v = work_.back ();
    work_.pop_back ();
    if (collapsible (v))
    {
      collapse<false> (classification_.predecessor[v.dim][v.id], work_, nullptr);
      ++collapses;
    }
  }
  return collapses;
}

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "wrap/classification.h"
#include "wrap/removal_log.h"
#include "delaunay/simplicial_complex.h"
#include "wrap/subcomplex.h"

#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Whether the pair of the flow (v, its predecessor tau) is free in \a y: both in Y, v
  * equivocal, and every coface of v in Y a face of tau (docs/design.md §5). */
inline bool
freePair (const Subcomplex& y, const Classification& classification, Simplex v)
{
  const Simplex tau = classification.predecessor[v.dim][v.id];
  if (tau.id == NO_SIMPLEX || !y.contains (v) || !y.contains (tau) || classification.of (v) != SimplexClass::equivocal)
    return false;
  // The k - l faces of tau one dimension above v are in Y (Y is a complex, tau is in it), and any
  // other coface xi of v has a vertex q outside tau, so v + q is one more coface one dimension up.
  // Counting those suffices.
  return y.cofaceCount (v) == static_cast<std::uint32_t> (tau.dim - v.dim);
}

/** \brief The collapses along the flow that shrink a subcomplex Y, and the deletions of principal
  * simplices between them (docs/design.md §5-6).
  *
  * A pair is free when the lower simplex's coface count in Y says that its only cofaces are faces
  * of the upper one (see collapsible()); a work queue holds the only places where a new free pair
  * can appear, the remaining facets of what was just removed. A whole retraction is linear in
  * the number of simplices. */
class Retraction
{
public:
  /** \param[in] log  told of every removal, or null. */
  Retraction (Subcomplex& y, const Classification& classification, RemovalLog* log = nullptr);

  const Subcomplex& subcomplex () const { return y_; }

  /** \brief Collapses while a pair is free, looking at every pair of the flow (Del S to X);
    * returns the number of collapses.
    * \param[in] order_seed 0 takes work on all threads; any other value on one, in a random
    *            order drawn from it (the result must not depend on it: docs/design.md §5). */
  std::size_t retract (std::uint64_t order_seed = 0);

  /** \brief Deletes \a s (§8) if it is principal in Y, telling its facets; returns whether it was
    * deleted. retractFreed() collapses what the deletion freed. */
  bool deletePrincipal (Simplex s);

  /** \brief Collapses while a pair is free, looking only where deletions since the last call
    * removed something. \a order_seed as for retract(), except that with 0 a retraction goes
    * on all threads only once it has made ALONE collapses on one: most are short. */
  std::size_t retractFreed (std::uint64_t order_seed = 0);

private:
  bool collapsible (Simplex v) const;
  /** Is \a v some simplex's lowest successor? Only an equivocal one can be: its one-byte class
    * is read first, which spares most of the predecessor array a pass over every simplex. */
  bool hasPredecessor (Simplex v) const
  {
    return classification_.of (v) == SimplexClass::equivocal &&
           classification_.predecessor[v.dim][v.id].id != NO_SIMPLEX;
  }
  /** Removes every xi with v <= xi <= tau (v is tau's lowest successor), queueing on \a work
    * the facets that stay. CONCURRENT and \a removed as for remove(). */
  template <bool CONCURRENT>
  void collapse (Simplex tau, std::vector<Simplex>& work, std::vector<Simplex>* removed);
  /** Takes \a xi out of Y, tells its facets, and queues on \a work the facets that stay.
    * CONCURRENT: other threads remove other simplices at the same time, and \a xi goes on
    * \a removed for the log instead of to it. */
  template <bool CONCURRENT>
  void remove (Simplex xi, unsigned removed_mask, Simplex tau, unsigned kept_below, std::vector<Simplex>& work,
               std::vector<Simplex>* removed);
  /** Collapses from the pairs on \a work until none is left, alongside other threads, putting
    * what it removes on \a removed (handed to the log in batches); after each collapse, \a share
    * may hand part of \a work to the other threads. */
  template <class Share>
  std::size_t collapseConcurrently (std::vector<Simplex>& work, std::vector<Simplex>& removed, const Share& share);
  /** Tells the log (if any) of \a removed, and empties it. */
  void handToLog (std::vector<Simplex>& removed);
  /** retract() from a fixed order, on all threads. */
  std::size_t retractInParallel ();
  /** retractFreed() on all threads. */
  std::size_t retractFreedInParallel ();

  /** Collapses a freed retraction makes on one thread before it goes on with all. */
  static constexpr std::size_t ALONE = 4096;
  /** The queued work a parallel retraction starts a thread with. */
  static constexpr std::size_t SHARED_WORK = 512;
  /** Removals a thread hands to the log at once. */
  static constexpr std::size_t LOGGED_TOGETHER = 8192;

  Subcomplex& y_;
  const SimplicialComplex& complex_;
  const Classification& classification_;
  RemovalLog* log_;
  std::vector<Simplex> work_;
};

} // namespace pcl_wrap::detail

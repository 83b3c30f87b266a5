// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "classification.h"
#include "portable.h"
#include "filled_in_parallel.h"
#include "simplicial_complex.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The subcomplex Y of Del S and the collapses that shrink it (docs/design.md §5).
  *
  * Y starts as Del S with omega already deleted (omega is never counted as a coface). Every
  * simplex keeps how many of its cofaces one dimension up are still in Y, which is all freeness
  * needs (see collapsible()), and a work queue holds the only places where a new collapsible
  * pair can appear: the remaining facets of what was just removed. A whole retraction is linear
  * in the number of simplices.
  */
class Retraction
{
public:
  Retraction (const SimplicialComplex& complex, const Classification& classification);

  /** \brief The same, taking over the counts of SimplicialComplex::releaseCofaceCounts(). */
  Retraction (const SimplicialComplex& complex, const Classification& classification,
              std::array<FilledInParallel<std::uint32_t>, 3> coface_counts);

  /** \brief Y = the simplices for which \a in_y is true (a subcomplex, e.g. X(delta) of the wrap
    * filtration), with its coface counts, for boundary extraction or further collapses. */
  Retraction (const SimplicialComplex& complex, const Classification& classification,
              const std::array<std::vector<std::uint8_t>, 4>& in_y);

  /** \brief Collapses while a pair is collapsible; returns the number of collapses.
    * \param[in] order_seed 0 takes work in a fixed order; any other value in a random order
    *            drawn from it (the result must not depend on it: docs/design.md §5). */
  std::size_t retract (std::uint64_t order_seed = 0);

  /** \brief Deletes \a s (§8) if it is in Y and principal (no coface in Y), telling its facets;
    * the next retract() collapses what the deletion freed. Returns whether it was deleted. */
  bool deletePrincipal (Simplex s);

  /** \brief Starts a trial: removals are logged until commitTrial() keeps them or
    * rollbackTrial() undoes them. */
  void beginTrial () { trial_.clear (); in_trial_ = true; }
  /** \brief The simplices removed since beginTrial(), in removal order. */
  const std::vector<Simplex>& trialRemovals () const { return trial_; }
  void commitTrial () { trial_.clear (); in_trial_ = false; }
  /** \brief Puts back everything removed since beginTrial(). */
  void rollbackTrial ();

  /** \brief From now on, every removed simplex remembers \a stamp (> 0): which deletion's
    * retraction removed it. */
  void stampRemovals (std::uint32_t stamp);
  /** \brief The stamp of the step that removed \a s; 0 while it is in Y or when nothing was
    * stamped. */
  std::uint32_t removalStamp (Simplex s) const { return stamps_[s.dim].empty () ? 0 : stamps_[s.dim][s.id]; }

  // Relaxed atomic loads (plain loads on x86): the first retraction runs on several threads.
  bool inY (Simplex s) const { return relaxedLoad (&alive_[s.dim][s.id]) != 0; }
  /** \brief Number of cofaces of \a s of dimension s.dim + 1 still in Y. */
  std::uint32_t cofacesInY (Simplex s) const
  {
    return s.dim < 3 ? relaxedLoad (&counts_[s.dim][s.id]) : 0;
  }

private:
  bool collapsible (Simplex v) const;
  /** Is \a v some simplex's lowest successor? Only an equivocal one can be: its one-byte class
    * is read first, which spares most of the predecessor array a pass over every simplex. */
  bool hasPredecessor (Simplex v) const
  {
    return classification_.of (v) == SimplexClass::equivocal && classification_.predecessor[v.dim][v.id].id != NO_SIMPLEX;
  }
  /** Removes every xi with v <= xi <= tau (v is tau's lowest successor), queueing on \a work
    * the facets that stay. CONCURRENT as for remove(). */
  template <bool CONCURRENT>
  void collapse (Simplex tau, std::vector<Simplex>& work);
  /** The first retraction of a fresh Y (no trial, no stamps, fixed order), on all threads. */
  std::size_t retractInParallel ();
  /** Counts every simplex of Y in its facets' coface counts. */
  void countCofaces ();
  /** Takes \a xi out of Y, tells its facets, and queues on \a work the facets that stay.
    * CONCURRENT: other threads remove other simplices at the same time. */
  template <bool CONCURRENT>
  void remove (Simplex xi, unsigned removed_mask, Simplex tau, unsigned kept_below, std::vector<Simplex>& work);

  const SimplicialComplex& complex_;
  const Classification& classification_;
  std::array<FilledInParallel<std::uint8_t>, 4> alive_;
  std::array<FilledInParallel<std::uint32_t>, 3> counts_; // per k-simplex: its (k+1)-cofaces in Y
  std::vector<Simplex> work_;
  bool seeded_ = false;
  std::array<std::vector<std::uint32_t>, 4> stamps_;
  std::uint32_t stamp_ = 0;
  std::vector<Simplex> trial_;
  bool in_trial_ = false;
};

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/simplicial_complex.h"
#include "wrap/subcomplex.h"

#include <array>
#include <cstdint>
#include <mutex>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief What a retraction removed from its subcomplex, for the deletions that look back:
  * - a trial (front deletion, docs/design.md §6): the removals since it began, in order, to keep
  *   or to put back;
  * - stamps (the wrap filtration): per simplex, which deletion's retraction removed it. */
class RemovalLog
{
public:
  explicit RemovalLog (const SimplicialComplex& complex) : complex_ (complex) {}

  /** \brief Called by the retraction for each simplex it takes out. */
  void record (Simplex s)
  {
    if (stamp_ != 0)
      stamps_[s.dim][s.id] = stamp_;
    if (in_trial_)
      trial_.push_back (s);
  }
  /** \brief record() for each of \a removed, from one of several threads that retract at once:
    * a trial's removals are then kept in no particular order. */
  void recordConcurrently (const std::vector<Simplex>& removed);

  /** \brief Starts a trial: removals are logged until commitTrial() keeps them or
    * rollbackTrial() puts them back. */
  void beginTrial ()
  {
    trial_.clear ();
    if (trial_.capacity () == 0) // room for every simplex: pages are touched only as it fills
      trial_.reserve (complex_.size (0) + complex_.size (1) + complex_.size (2) + complex_.size (3));
    in_trial_ = true;
  }
  /** \brief The simplices removed since beginTrial(), in removal order within each run of the
    * retraction on one thread. */
  const std::vector<Simplex>& trialRemovals () const { return trial_; }
  void commitTrial ()
  {
    trial_.clear ();
    in_trial_ = false;
  }
  /** \brief Puts back into \a y everything removed since beginTrial() (Subcomplex::putBack()
    * gives the same Y in any order). */
  void rollbackTrial (Subcomplex& y);

  /** \brief From now on, every removed simplex remembers \a stamp (> 0). */
  void stampRemovals (std::uint32_t stamp);
  /** \brief The stamp of the step that removed \a s; 0 while it is in Y or before any stamping. */
  std::uint32_t stamp (Simplex s) const { return stamps_[s.dim].empty () ? 0 : stamps_[s.dim][s.id]; }

private:
  const SimplicialComplex& complex_;
  std::array<std::vector<std::uint32_t>, 4> stamps_;
  std::uint32_t stamp_ = 0;
  std::vector<Simplex> trial_;
  std::mutex trial_mutex_;
  bool in_trial_ = false;
};

} // namespace pcl_wrap::detail

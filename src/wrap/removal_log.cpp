// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap/removal_log.h"

namespace pcl_wrap::detail
{

void
RemovalLog::rollbackTrial (Subcomplex& y)
{
  for (auto it = trial_.rbegin (); it != trial_.rend (); ++it)
  {
    y.putBack (*it);
    if (!stamps_[it->dim].empty ())
      stamps_[it->dim][it->id] = 0;
  }
  trial_.clear ();
  in_trial_ = false;
}

void
RemovalLog::recordConcurrently (const std::vector<Simplex>& removed)
{
  if (stamp_ != 0)
    for (const Simplex s : removed)
      stamps_[s.dim][s.id] = stamp_; // a simplex is removed once: no other thread writes it
  if (in_trial_)
  {
    const std::lock_guard<std::mutex> lock (trial_mutex_);
    trial_.insert (trial_.end (), removed.begin (), removed.end ());
  }
}

void
RemovalLog::stampRemovals (std::uint32_t stamp)
{
  if (stamps_[0].empty ())
    for (int k = 0; k <= 3; ++k)
      stamps_[k].assign (complex_.size (k), 0);
  stamp_ = stamp;
}

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <chrono>
#include <string>

namespace pcl_wrap::detail
{

/** \brief Times consecutive stages into WrapStatistics::timings and tells the observer. */
class StageClock
{
public:
  StageClock (WrapStatistics& stats, const StageObserver& observer)
    : stats_ (stats), observer_ (observer), start_ (Clock::now ())
  {}

  /** \brief Ends the current stage (which began at the previous call or at construction). */
  void stageDone (const std::string& stage)
  {
    const auto now = Clock::now ();
    const double seconds = std::chrono::duration<double> (now - start_).count ();
    start_ = now;
    stats_.timings.push_back ({stage, seconds});
    stats_.total_seconds += seconds;
    if (observer_)
      observer_ (stage, seconds);
  }

private:
  using Clock = std::chrono::steady_clock;
  WrapStatistics& stats_;
  const StageObserver& observer_;
  Clock::time_point start_;
};

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/wrap_parameters.h>
#include <pcl_wrap/wrap_result.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace pcl_wrap
{

using Point3 = std::array<double, 3>;

/** \brief Called after each stage with its name and duration, e.g. to show progress. */
using StageObserver = std::function<void (const std::string& stage, double seconds)>;

/** \brief The Wrap construction on plain points: the engine behind pcl_wrap::Wrap.
  *
  * \param[in] points the input points; non-finite ones are skipped and reported, exact duplicates
  *            are kept once (the first), the others reported
  * \param[in] parameters see WrapParameters
  * \param[in] observer optional, called after every stage
  * \return the surface W, the complex and statistics, with indices into \a points
  */
WrapResult
computeWrap (const std::vector<Point3>& points,
             const WrapParameters& parameters = WrapParameters (),
             const StageObserver& observer = StageObserver ());

} // namespace pcl_wrap

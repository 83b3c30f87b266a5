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

/** \brief Called while a long stage runs (the triangulation of large inputs) with the share of
  * it done, from 0 to 1, e.g. to show a progress bar. */
using ProgressObserver = std::function<void (const std::string& stage, double done)>;

/** \brief Throws std::invalid_argument, saying why, when computeWrap() would reject
  * \a parameters: a NaN or non-positive threshold, a non-finite weight scale, a malformed region,
  * or a region without front deletion and a size threshold. Lets an application check what a
  * user asked for before it reads any points. */
void
checkParameters (const WrapParameters& parameters);

/** \brief The Wrap construction on plain points: the engine behind pcl_wrap::Wrap.
  *
  * \param[in] points the input points; points with a non-finite coordinate or weight are
  *            skipped and reported; of the points at one position the one with the largest
  *            weight (then the smallest index) is kept, the others reported as duplicates
  * \param[in] weights empty (every weight 0) or one per point, scaled by
  *            WrapParameters::weight_scale; points whose power cell is empty are hidden: reported,
  *            never part of the output
  * \param[in] parameters see WrapParameters
  * \param[in] observer optional, called after every stage; an exception it throws (e.g. to
  *            cancel) ends the computation and reaches the caller
  * \param[in] progress optional, called within long stages
  * \return the surface (by default the default surface, a closed oriented 2-manifold through the
  *         points; see WrapParameters::output), the complex when asked and statistics, with
  *         indices into \a points
  * \throws std::invalid_argument when \a weights is neither empty nor one per point, or from
  *         checkParameters()
  */
WrapResult
computeWrap (const std::vector<Point3>& points, const std::vector<double>& weights,
             const WrapParameters& parameters = WrapParameters (), const StageObserver& observer = StageObserver (),
             const ProgressObserver& progress = ProgressObserver ());

/** \brief computeWrap() with every weight 0. */
WrapResult
computeWrap (const std::vector<Point3>& points,
             const WrapParameters& parameters = WrapParameters (),
             const StageObserver& observer = StageObserver ());

/** \brief The median distance from a point to its nearest neighbour, from the Delaunay
  * triangulation of the distinct finite points, in double precision: the spacing that
  * Threshold::relativeRadius() is relative to (with weights, the construction takes the nearest
  * neighbour among the points sharing a simplex of the regular triangulation). 0 for fewer than
  * two distinct points. */
double
medianSpacing (const std::vector<Point3>& points);

} // namespace pcl_wrap

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <cmath>

namespace pcl_wrap::detail
{

/** \brief |p - q|^2 in double precision: a measure for the surface stage's choices, never a
  * predicate of the construction. */
inline double
squaredDistance (const Point3& p, const Point3& q)
{
  return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
}

inline double
distance (const Point3& p, const Point3& q)
{
  return std::sqrt (squaredDistance (p, q));
}

} // namespace pcl_wrap::detail

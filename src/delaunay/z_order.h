// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The indices of \a points (finite) along a Z-order (Morton) curve through their bounding box, 21
  * bits per axis; points in one cell of that grid by index. Nearby points get nearby positions,
  * which is all the order is for: arrays indexed in it stay in cache. It depends only on the
  * points. Its keys sort in parallel, several times faster than CGAL's Hilbert sort. */
std::vector<std::uint32_t>
zOrder (const std::vector<Point3>& points);

} // namespace pcl_wrap::detail

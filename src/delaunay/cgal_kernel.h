// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// The one place that names the CGAL kernel: exact predicates, inexact constructions.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace pcl_wrap::detail
{

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using WeightedPoint = Kernel::Weighted_point_3;
using BarePoint = Kernel::Point_3;

} // namespace pcl_wrap::detail

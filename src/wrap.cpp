// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// Precompiled instantiations of pcl_wrap::Wrap for PCL's XYZ point types.
#include <pcl_wrap/impl/wrap.hpp>

#include <pcl/impl/instantiate.hpp>
#include <pcl/point_types.h>

#ifndef PCL_NO_PRECOMPILE
PCL_INSTANTIATE (Wrap, PCL_XYZ_POINT_TYPES)
#endif

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <string>
#include <vector>

namespace pcl_wrap::bench
{

/** \brief N points on a sphere (radius 1, 1e-3 radial noise), a torus (radii 1 and 0.4, uniform in
  * angle), a terrain (z = 0.2 sin 3x cos 2y over [-1, 1]^2, seen from above only), a rough terrain
  * (the same with bumps of 0.02 a wavelength of 0.16 and Gaussian noise of a fifth of the spacing
  * 2 / sqrt N in z), a half sphere (z >= 0, one side of a scan) or in a cube ([-1, 1]^3), from
  * \a seed; or the points of a file (N ignored). */
std::vector<Point3>
makePoints (const std::string& shape, std::size_t n, unsigned seed);

/** \brief The diagonal of the points' bounding box (0 for none). */
double
boundingBoxDiagonal (const std::vector<Point3>& points);

} // namespace pcl_wrap::bench

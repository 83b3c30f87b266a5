// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "surface/solid_labelling.h"

#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Fills the voids of the solid that no inner surface's points show: each connected part of
  * the outside tetrahedra that does not reach the convex hull is a void, and one with fewer than
  * FRAGMENT_VERTICES vertices (a bubble of a few tetrahedra between noisy points) moves inside. A
  * void the points sample, the inside of a hollow ball, stays. On all threads but the filling.
  * \param[in,out] moved per tetrahedron, set for those it moves
  * \return the tetrahedra it moved inside, ascending */
std::vector<std::uint32_t>
fillUnsampledVoids (const Tetrahedra& tetrahedra, SolidLabels& labels, std::vector<std::uint8_t>& moved);

} // namespace pcl_wrap::detail

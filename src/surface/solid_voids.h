// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "surface/solid_labelling.h"
#include "surface/solid_parts.h"

#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Fills the voids of the solid that no inner surface's points show: each connected part of
  * the outside tetrahedra that does not reach the convex hull is a void, and one with fewer than
  * FRAGMENT_VERTICES vertices (a bubble of a few tetrahedra between noisy points) moves inside. A
  * void the points sample, the inside of a hollow ball, stays. On all threads but the filling.
  * \param[in,out] moved per tetrahedron, set for those it moves
  * \param[in,out] sides the parts of the outside of \a labels, or of both sides; the voids filled
  *                join the solid's
  * \param[out] kept if given, the tetrahedra of the voids it keeps are appended, ascending
  * \return the tetrahedra it moved inside, ascending */
std::vector<std::uint32_t>
fillUnsampledVoids (const Tetrahedra& tetrahedra, SolidLabels& labels, std::vector<std::uint8_t>& moved,
                    SideParts& sides, std::vector<std::uint32_t>* kept = nullptr);

/** \brief fillUnsampledVoids() with the parts found here. */
std::vector<std::uint32_t>
fillUnsampledVoids (const Tetrahedra& tetrahedra, SolidLabels& labels, std::vector<std::uint8_t>& moved);

/** \brief fillUnsampledVoids() after a few tetrahedra \a changed side in a solid that had no void
  * to fill: such a void now holds one of them or lies next to one, so only the outside tetrahedra
  * connected to those are searched, each search ending at the hull or at FRAGMENT_VERTICES
  * vertices. Fills the same voids, in time proportional to the change. */
std::vector<std::uint32_t>
fillUnsampledVoidsNear (const Tetrahedra& tetrahedra, SolidLabels& labels, std::vector<std::uint8_t>& moved,
                        const std::vector<std::uint32_t>& changed);

} // namespace pcl_wrap::detail

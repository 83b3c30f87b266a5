// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "surface/solid_labelling.h"
#include "wrap/subcomplex.h"

#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The connected parts of a solid, through the facets its tetrahedra share. */
struct SolidParts
{
  static constexpr std::uint32_t NO_PART = ~std::uint32_t (0);
  /** \brief Per tetrahedron, its part (NO_PART outside), numbered in the order of their lowest
    * tetrahedra. */
  std::vector<std::uint32_t> part;
  std::vector<std::uint32_t> size; ///< per part, its tetrahedra
};

/** \brief The parts of the solid \a inside, on all threads; they do not depend on the number of
  * threads. */
SolidParts
solidParts (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside);

/** \brief Joins the connected parts of the solid that X's tetrahedra join: from each part but the
  * largest, smallest first, the cheapest path (by summed margins) of outside tetrahedra of X to
  * another part moves inside. X is contractible, so a part cut off the solid by the labelling (a
  * thin leg, a horn) is tied to the rest through X; separate objects are not, as X joins them
  * through lower-dimensional simplices only. A tetrahedron of X is one of X's tetrahedra or has a
  * triangle of X (a sheet, where the retraction thinned a part of the solid to nothing).
  * \param[in,out] moved per tetrahedron, set for those it moves
  * \return the tetrahedra it moved inside, in the order it moved them */
std::vector<std::uint32_t>
joinPartsThroughX (const Tetrahedra& tetrahedra, const Subcomplex& x, SolidLabels& labels,
                   std::vector<std::uint8_t>& moved);

} // namespace pcl_wrap::detail

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

/** \brief Cuts the ties that the labelling made across a void between separate objects: an inner
  * object (a ball inside a hollow sphere) tied to the wall around it by a pillar of tetrahedra
  * across the empty gap between them, which noise of about a spacing can leave inside.
  *
  * The points fall into clusters, tied by Delaunay edges across no gap that the sampling resolves
  * at NECK_GAP spacings (the spacing around each end, spacingAround()). Where the surface of a void
  * (a part of the outside that does not reach the hull) passes through two clusters of
  * FRAGMENT_VERTICES points or more, each an object of its own, the solid's tetrahedra with corners
  * in two such clusters of one void tie them across the void: they move outside, unless a point
  * on the solid's surface would then be on it no more. A void's surface that is one cluster, the
  * inside of a hollow ball, has nothing to cut; nor has a solid with no void.
  * \param[in] positions per vertex
  * \param[in] in_voids the tetrahedra of the voids of \a labels (fillUnsampledVoids()'s kept)
  * \param[in,out] moved per tetrahedron, set for those it moves
  * \param[in] sides the parts of the outside of \a labels (or of both sides)
  * \return the tetrahedra it moved outside, ascending */
std::vector<std::uint32_t>
cutTiesAcrossVoids (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions,
                    const std::vector<std::uint32_t>& in_voids, SolidLabels& labels, std::vector<std::uint8_t>& moved,
                    SideParts& sides);

} // namespace pcl_wrap::detail

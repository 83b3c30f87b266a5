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

/** \brief What bringPointsOfWOn() did. */
struct PointsOfWBrought
{
  std::vector<std::uint32_t> moved;    ///< the tetrahedra moved, one per point brought on
  std::vector<std::uint32_t> left_off; ///< the points of W that no move reached
  std::size_t on_surface_off_w = 0;    ///< points on the surface and not on W
};

/** \brief Brings onto the solid's surface the points that the paper's W has and the surface has
  * not, where one tetrahedron does it, so that the surface loses none of W's points that it
  * could keep by so small a move.
  *
  * A point is on W unless X holds its whole star (and it is not on the hull); it is on the solid's
  * surface when its star has tetrahedra on both sides (a hull vertex: one inside). A point on W
  * but not on the surface has its whole star on one side. A tetrahedron of that star whose facet
  * opposite the point is on the surface changes side: the surface then runs over the point by
  * the tetrahedron's three other facets, and stays a closed 2-manifold wherever it was one (the
  * three are new to it, and so is the point), with its pieces and genus. Of several such
  * tetrahedra, the one whose longest edge is shortest moves, of those within one group of the
  * sample (SolidLabels::group: one across the gap between two groups would be a spike); a point
  * none reaches stays off, and so does a point apart from all others (SolidLabels::apart).
  * \param[in] positions per vertex */
PointsOfWBrought
bringPointsOfWOn (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
                  SolidLabels& labels);

/** \brief Does the solid's surface (its tetrahedra's \a labels) that bringPointsOfWOn() left
  * (\a brought) have fewer points on it than the triangles of the paper's W = Bd X, the points
  * apart from all others (SolidLabels::apart) not counted? Where the stars of the points it left
  * off show that it has not, nothing else is looked at. */
bool
fewerPointsThanW (const Tetrahedra& tetrahedra, const Subcomplex& x, const SolidLabels& labels,
                  const PointsOfWBrought& brought);

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "boundary.h"
#include "filled_in_parallel.h"
#include "manifold_split.h"
#include "simplicial_complex.h"
#include "subcomplex.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Is the sample a single layer, with no volume behind it (a terrain, a scan seen from one
  * side)? Then Wrap's flow has collapsed the space under the points, and most of the tetrahedra
  * that the labelling put inside, which close the layer with its convex hull, are not in X.
  * On a closed object X holds nearly all of them (it is larger than the solid: it webs across
  * concavities). */
bool
isSingleLayer (const SimplicialComplex& complex, const Subcomplex& x, const std::vector<std::uint8_t>& inside);

/** \brief The number of distinct vertices of \a triangles. */
std::size_t
verticesOn (const std::vector<std::array<std::uint32_t, 3>>& triangles);

/** \brief The surface of a single-layer sample: X's boundary split into a closed two-sided shell. */
struct TwoSidedShell
{
  Boundary w;           ///< the boundary of X and the bridges
  ManifoldSplit split;  ///< w split where it touches itself, sheets once per side
  std::size_t bridges = 0; ///< Delaunay triangles added to tie pieces to the rest
};

/** \brief X's boundary, split into a closed 2-manifold (a sheet once per side, points copied per
  * side), with as few pieces as the split allows. The split separates pieces of X that meet at a
  * single vertex, or that it splits apart along an edge (a triangle at the rim of a scan, hanging
  * from one corner), which would come out as closed pieces of their own; each is tied to the rest
  * by the fewest Delaunay triangles around the shared vertex that join them, added as a sheet,
  * until a round ties nothing new. They are faces of the triangulation, so the shell still cannot
  * intersect itself.
  * \param[in] neighbours per tetrahedron, the tetrahedron across each facet, as for SolidLabelling */
TwoSidedShell
twoSidedShell (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours, const Subcomplex& x);

} // namespace pcl_wrap::detail

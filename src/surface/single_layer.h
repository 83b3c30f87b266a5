// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/simplicial_complex.h"
#include "delaunay/tetrahedra.h"
#include "wrap/boundary.h"
#include "wrap/manifold_split.h"
#include "wrap/subcomplex.h"

#include <pcl_wrap/compute_wrap.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief X's triangles on none of its tetrahedra (a sheet's) and on one (bounding a solid). */
struct LayerTriangles
{
  std::size_t sheet = 0, bounding = 0;

  /** \brief Is the sample a single layer, with no volume behind it (a terrain, a scan seen from
    * one side)? Then Wrap's flow has collapsed the space under the points, and X is the layer
    * itself (the paper's Figure 3): most of its triangles are faces of none of its tetrahedra. On
    * a closed object X is a solid, and nearly all of its triangles that are not inside it bound
    * it: the sample is a single layer when X has more sheet triangles than bounding ones. */
  bool singleLayer () const { return sheet > bounding; }

  /** \brief Is X at least partly a sheet: half as many sheet triangles as bounding ones or more
    * (a third of its surface)? Noise of about a spacing across a single layer leaves X a sheet
    * torn by thin solids, where the noise took points off the layer; on a closed object, noisy or
    * not, X's sheets are a few per cent of its surface. */
  bool partlySheet () const { return 2 * sheet >= bounding; }
};

/** \brief X's sheet and bounding triangles; none where the complex is not 3-dimensional. */
LayerTriangles
layerTriangles (const SimplicialComplex& complex, const Subcomplex& x);

/** \brief layerTriangles (complex, x).singleLayer (). */
bool
isSingleLayer (const SimplicialComplex& complex, const Subcomplex& x);

/** \brief Appends to \a w X's triangles inside it, between two of its tetrahedra, as the complex
  * lists their vertices: with W's, every triangle of X. */
void
addInnerTriangles (const SimplicialComplex& complex, const Subcomplex& x, Boundary& w);

/** \brief The number of distinct vertices of \a triangles. */
std::size_t
verticesOn (const std::vector<std::array<std::uint32_t, 3>>& triangles);

/** \brief The surface of a single-layer sample: X's boundary split into a closed two-sided shell. */
struct TwoSidedShell
{
  Boundary w;           ///< the boundary of X and the bridges
  ManifoldSplit split;  ///< w split where it touches itself, sheets once per side
  std::size_t bridges = 0; ///< Delaunay simplices added: tents to points on no triangle, ties of pieces
};

/** \brief X's boundary, split into a closed 2-manifold (a sheet once per side, points copied per
  * side), with fewer pieces than the split alone gives. The split separates pieces of X that
  * meet at a single vertex, or that it cannot keep joined along an edge (a triangle hanging from
  * the rim of a scan), which come out as closed pieces of their own. First, a point that X holds
  * by a dangling edge alone gets a tent (tentsToLonePoints()). In rounds, each piece is tied to
  * another at a vertex they share by Delaunay simplices around it (the tetrahedra around a shared
  * edge, or the triangles around the vertex, whose largest is as small as can be), none longer
  * than the triangles they join nor meeting the shell along another edge; a round is kept only
  * if it leaves fewer pieces and no new handle (shellTies()). The ties are faces of the
  * triangulation. Pieces left meeting only along an edge are joined there by taking the other
  * diagonal of the quadrilaterals around it (joinAlongSharedEdges()): the only triangles of the
  * shell that are not Delaunay faces.
  * \param[in] tetrahedra attached to their complex
  * \param[in] positions per vertex */
TwoSidedShell
twoSidedShell (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions, const Subcomplex& x);

} // namespace pcl_wrap::detail

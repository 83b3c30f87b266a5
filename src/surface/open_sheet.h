// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "wrap/boundary.h"

#include <pcl_wrap/compute_wrap.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The surface of a single layer (a terrain, a scan seen from one side): one open,
  * oriented 2-manifold with boundary through the points, each point once.
  *
  * Wrap's X of such a sample is the layer itself (the paper's Figure 3), a sheet of triangles that
  * thickens into tetrahedra where the points are noisy; its boundary W has the sheet's triangles
  * once and the thick parts' triangles on both sides. The sheet is grown from one of W's triangles
  * across the edges it reaches, one triangle at a time, keeping every edge on at most two
  * triangles traversed both ways:
  * - first the triangles that fill a notch of the front (two of their edges on it), so that the
  *   front stays short and meets itself rarely;
  * - then those that bring a new point, smallest first: at a thick part, the side through more of
  *   its points;
  * - then the rest.
  * A point on W by a dangling edge alone is brought on by the smallest Delaunay triangle around
  * that edge that fits the front. A triangle may touch the front at a point where the front meets
  * itself; where the fans around a point do not join into one by the end, all but the largest are
  * dropped. A W triangle the growth does not reach seeds a sheet of its own (a separate part).
  *
  * A triangle with an edge longer than 3.5 times the spacing at both of its ends (the length of
  * their third-shortest edges in W) spans a gap the sampling resolves and is left out: separate
  * parts stay apart. Then Delaunay triangles whose points are each on the front or on no sheet yet
  * close the cracks where X cut a ring-shaped layer and reach the points X buried (where it fills
  * the corner between a wall and the ground). A point the sheets miss gets a tent: a sheet
  * triangle that is a facet of a Delaunay tetrahedron with the point as its apex is replaced by
  * the other three facets; where none is, a cone: a strip of up to three sheet triangles, or an
  * edge of a sheet's boundary, is replaced by the Delaunay triangles from the point over its rim.
  * A crumb the growth left beside a much larger sheet is taken off first, so that its points come
  * onto that sheet. Holes smaller than a gap are closed by ear clipping. A point that no tent or
  * cone reaches is pinned: a sheet triangle or boundary edge at one of its Delaunay neighbours
  * gets the triangles from the point over it, which need not be Delaunay faces.
  *
  * With \a noisy (a layer with noise across it of about a spacing, which only a coarser sample
  * found), the growth does not turn the sheet over: each point has a direction across the layer,
  * from a structure tensor over about two rings of its Delaunay neighbours; a seed's points take
  * the side of it their triangle faces, a point the growth brings in the side its front edge's
  * points face, and a triangle that would face the other way at one of its points is refused
  * (a point too sparsely connected for a direction refuses none). Without it, steep triangles
  * between points at different depths turn the sheet over a little at a time, and the regions
  * turned over cannot join those that are not: the sheet comes out torn by long cracks, about
  * half of it facing down.
  *
  * Each connected sheet faces \a viewpoint when one is given; otherwise up (+z: terrains, aerial
  * scans), and a sheet with no up or down (a vertical wall) away from the solid its points close
  * with their convex hull (the labelled solid: \a inside flags its tetrahedra, called only then).
  * \param[in] tetrahedra attached to their complex
  * \param[in] w the boundary of X, with its triangles' ids */
Boundary
openSheet (const Tetrahedra& tetrahedra, Boundary w, const std::vector<Point3>& positions,
           const std::function<std::vector<std::uint8_t> ()>& inside, const std::optional<Point3>& viewpoint,
           bool noisy);

} // namespace pcl_wrap::detail

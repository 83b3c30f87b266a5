// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "surface/solid_labelling.h"
#include "wrap/boundary.h"
#include "wrap/subcomplex.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief What repairSolid() changed. */
struct SolidRepair
{
  std::size_t flipped = 0;          ///< tetrahedra moved to the other side
  std::vector<std::uint32_t> pinched; ///< vertices where the surface still touches itself, ascending
  /** The repaired solid's surface, extractSolidBoundary() of its labels, when the repair read it
    * off after its last move (to look for handles): so it need not be read off again. */
  std::optional<Boundary> surface;
};

/** \brief Moves tetrahedra across the surface of the solid in \a labels, weakest votes first,
  * until the surface is a 2-manifold through every vertex it can reach:
  * - at an edge with more than two surface triangles (the solid touches itself along it), the
  *   weakest run of tetrahedra around the edge changes side, which joins the runs beside it;
  * - at a vertex whose triangles make more than one fan, the weakest connected part of its star
  *   changes side;
  * - a vertex buried inside the solid (or floating outside it) gets its weakest tetrahedron that
  *   touches the surface moved out (or in), which puts it on the surface; with \a keep_buried
  *   (the points sample a volume) a vertex buried from the start stays inside.
  * - parts of the solid cut off from the rest are joined to it along X (joinPartsThroughX());
  * - then small handles (smallHandlePatches()) are cut or filled where moving one connected part
  *   of a star, or of the tetrahedra within a patch around the handle, takes exactly one handle
  *   away;
  * - first, the voids no inner surface's points show are filled (fillUnsampledVoids()).
  * Each tetrahedron changes side at most once in the mending, so the repair ends; a pinch it
  * cannot mend is left to the pinch split (splitSolidPinches()).
  * \param[in] tetrahedra attached to their complex
  * \param[in] positions per vertex */
SolidRepair
repairSolid (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
             SolidLabels& labels, bool keep_buried = false);

} // namespace pcl_wrap::detail

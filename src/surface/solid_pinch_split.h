// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "wrap/boundary.h"
#include "wrap/manifold_split.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Splits the boundary \a w of a solid (the tetrahedra flagged in \a inside) at the few
  * vertices of \a pinched where it touches itself, looking only at their stars: the same split
  * as splitPinches() with the solid as X. Around a pinched vertex, two triangles along an edge
  * belong to one fan when a run of outside tetrahedra around the edge joins them (solid parts
  * that touch along the edge stay joined there), or, where that joins two copies of the edge to
  * the same two vertices, a run of solid ones. The first fan (by lowest triangle id) keeps the
  * vertex, every other gets a copy.
  * \param[in] tetrahedra attached to their complex
  * \param[in] pinched every vertex where the triangles of \a w do not make one fan
  * \return nothing where an edge with more than four triangles needs yet another way to glue
  *         them; splitPinches() then decides */
std::optional<ManifoldSplit>
splitSolidPinches (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside, const Boundary& w,
                   const std::vector<std::uint32_t>& pinched);

} // namespace pcl_wrap::detail

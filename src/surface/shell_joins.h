// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "wrap/manifold_split.h"

#include <cstddef>
#include <cstdint>

namespace pcl_wrap::detail
{

/** \brief Joins pieces of \a split (a closed two-sided shell over \a nv vertices) that meet only
  * along an edge (a, b), two triangles each: taken in a cycle, piece i's triangle (a, b, u) and
  * the next piece's (b, a, w) take the other diagonal, (a, w, u) and (w, b, u), and the pieces'
  * copies of a and b become one. Every edge stays in two triangles, once each way, and k spheres
  * make one. Returns how many pieces it joined to others. */
std::size_t
joinAlongSharedEdges (ManifoldSplit& split, std::uint32_t nv);

/** \brief Drops the copies of points that no triangle of \a split uses any more. */
void
dropUnusedCopies (ManifoldSplit& split, std::uint32_t nv);

} // namespace pcl_wrap::detail

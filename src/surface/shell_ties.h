// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "wrap/manifold_split.h"

#include <pcl_wrap/compute_wrap.h>

#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The Delaunay simplices that tie together pieces of a two-sided shell \a split (over the
  * vertices of \a tetrahedra, copies after them) that share a vertex. For each pair of pieces to
  * tie, at their lowest shared vertex u: the tetrahedra around an edge (u, a) they share, from one
  * piece's triangle to the other's, which make the pieces one solid wedge there; or, where they
  * share only u, the triangles around u from one to the other. Either way round, the path whose
  * largest simplex is smallest, only through simplices that meet no other edge of the shell (the
  * tie would close a loop through it: a handle) and are no longer than the triangles they join (a
  * longer one would lie across the layer).
  * \param[in] positions per vertex
  * \param[in] edge_in_k per edge of the complex, whether it is in the complex that was split */
std::vector<Simplex>
shellTies (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions,
           const std::vector<std::uint8_t>& edge_in_k, const ManifoldSplit& split);

} // namespace pcl_wrap::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "util/filled_in_parallel.h"
#include "wrap/subcomplex.h"
#include "delaunay/simplicial_complex.h"

#include <pcl_wrap/wrap_result.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief W = Bd X (docs/design.md §5) in vertex ids of the complex. */
struct Boundary
{
  /** \brief Oriented away from the tetrahedron of X behind them; triangles with none behind
    * them (sheets) oriented consistently across every edge shared by exactly two of them. */
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /** \brief The id in the complex of each of the triangles. */
  std::vector<SimplexId> triangle_ids;
  std::vector<std::array<std::uint32_t, 2>> dangling_edges;
  std::vector<std::uint32_t> isolated_vertices;
};

/** \brief The boundary of the subcomplex \a x (X, or a solid's closure). With \a orient_sheets
  * false, its sheets' triangles (on no tetrahedron of \a x) are left as the complex lists their
  * vertices, for a caller that turns them itself. */
Boundary
extractBoundary (const SimplicialComplex& complex, const Subcomplex& x, bool orient_sheets = true);

/** \brief The boundary of the tetrahedra flagged in \a inside (which have no lower-dimensional
  * parts to leave sheets): the facets between an inside and an outside tetrahedron, or the hull,
  * oriented away from the inside one, in the order of the tetrahedra.
  * \param[in] tetrahedra attached to their complex */
Boundary
extractSolidBoundary (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside);

} // namespace pcl_wrap::detail

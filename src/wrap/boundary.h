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
#include <functional>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief For a positively oriented tetrahedron, the facet opposite local vertex i listed so that
  * its normal points away from vertex i: orientation (a, b, c, v_i) < 0 for (a, b, c) below. */
constexpr int OUTWARD_FACET[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

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

/** \brief The boundary of the subcomplex \a x (X, or a solid's closure). Its sheets' triangles (on
  * no tetrahedron of \a x) are turned by orientSheetTriangles() with \a sheet_key (the vertex ids
  * when empty); with \a orient_sheets false they are left as the complex lists their vertices, for
  * a caller that turns them itself. */
Boundary
extractBoundary (const SimplicialComplex& complex, const Subcomplex& x, bool orient_sheets = true,
                 const std::function<std::uint32_t (std::uint32_t)>& sheet_key = {});

/** \brief Turns \a triangles (a sheet, or several) so that neighbours across an edge shared by
  * exactly two of them traverse it in opposite directions. Each connected sheet takes its turn
  * from its triangle with the smallest keys, listed in ascending keys; \a key gives each vertex a
  * distinct number. The result depends only on the set of triangles and the keys, so a process
  * that holds the same triangles under other vertex ids turns them the same way. */
void
orientSheetTriangles (std::vector<std::array<std::uint32_t, 3>>& triangles,
                      const std::function<std::uint32_t (std::uint32_t)>& key);

/** \brief The boundary of the tetrahedra flagged in \a inside (which have no lower-dimensional
  * parts to leave sheets): the facets between an inside and an outside tetrahedron, or the hull,
  * oriented away from the inside one, in the order of the tetrahedra.
  * \param[in] tetrahedra attached to their complex */
Boundary
extractSolidBoundary (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside);

} // namespace pcl_wrap::detail

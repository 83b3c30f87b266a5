// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "wrap/boundary.h"
#include "wrap/subcomplex.h"
#include "delaunay/simplicial_complex.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief W's triangles as a closed combinatorial 2-manifold (docs/design.md §8). */
struct ManifoldSplit
{
  /** \brief Oriented triangles; a vertex id v >= numVertices() is a copy of copy_of[v -
    * numVertices()]. A sheet triangle appears once per side, in opposite orientations. */
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> copy_of;
  /** \brief The vertex that \a v is or copies, for a complex of \a nv vertices. */
  std::uint32_t original (std::uint32_t v, std::uint32_t nv) const { return v < nv ? v : copy_of[v - nv]; }
  std::size_t pinch_edges = 0;     ///< edges of W on more than two sides, split
  std::size_t pinch_vertices = 0;  ///< vertices whose triangles form more than one fan, split
  std::size_t sheet_triangles = 0; ///< triangles with the outside on both sides, doubled
};

/** \brief Splits W (\a w, the boundary of \a x) where it touches itself. Each triangle side that
  * faces the outside is a face; around an edge, the two faces that bound the same sector of the
  * outside (a run of tetrahedra not in X, found by walking around the edge in Del S) are glued;
  * then every vertex gets one copy per fan of faces glued around it. The faces are the boundary
  * of a thickened X, hence a closed oriented 2-manifold; where two pockets of the outside touch
  * only along an edge, which would join two copies of the edge to the same two vertices, the
  * faces there are glued across X instead.
  * \throws std::logic_error if W is not closed (it always is: docs/design.md §5) */
ManifoldSplit
splitPinches (const SimplicialComplex& complex, const Subcomplex& x, const Boundary& w);

/** \brief An undirected edge as one key: the lower vertex id in the high half. */
std::uint64_t
edgeKey (std::uint32_t a, std::uint32_t b);

/** \brief The undirected edges (as keys) of \a triangles not in exactly two of them traversed
  * both ways. None: with every vertex's triangles one fan, a closed oriented 2-manifold. */
std::vector<std::uint64_t>
nonManifoldEdges (const std::vector<std::array<std::uint32_t, 3>>& triangles);

} // namespace pcl_wrap::detail

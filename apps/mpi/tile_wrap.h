// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "tile_complex.h"

#include "wrap/subcomplex.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief The simplices of X and W that belong to one tile, in indices of S. */
struct TileWrap
{
  std::array<std::size_t, 4> x_count{}; ///< per dimension, the number of simplices of X
  /** W's triangles with a tetrahedron of X behind them, facing away from it. */
  std::vector<std::array<std::uint32_t, 3>> faces;
  /** W's triangles on no tetrahedron of X, not yet turned (orientSheetTriangles() does that once
    * they are all in one place). */
  std::vector<std::array<std::uint32_t, 3>> sheets;
  std::vector<std::array<std::uint32_t, 2>> dangling_edges; ///< smaller index first
  std::vector<std::uint32_t> isolated_vertices;
};

/** \brief What of X (the retracted \a y) and of W = Bd X belongs to this tile. */
TileWrap
extractTileWrap (const TileComplex& tile, const detail::Subcomplex& y);

} // namespace pcl_wrap::mpi

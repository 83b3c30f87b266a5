// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "tile_complex.h"

#include "point_file.h"

#include "util/stage_clock.h"
#include "wrap/subcomplex.h"

#include <pcl_wrap/compute_wrap.h>
#include <pcl_wrap/wrap_parameters.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief The tetrahedra of Del S that belong to one tile, in indices of S, positively oriented,
  * and whether each is in X: what the tile sends rank 0 for the default surface. */
struct TileSolid
{
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
  std::vector<std::uint8_t> in_x;
};

/** \brief This tile's part of Del S's tetrahedra, and of X's (the retracted \a y). */
TileSolid
tileSolid (const TileComplex& tile, const detail::Subcomplex& y);

/** \brief On rank 0, from every tile's TileSolid: pcl_wrap's output after the construction, the
  * sink deletion of a threshold (if \a parameters set one) and the default surface
  * (docs/surface.md), or the paper's W (Output::raw); with WrapParameters::keep_complex, the
  * complex as pcl_wrap lists it too, the classes found again (and with WrapParameters::filtration
  * the wrap filtration).
  *
  * These run as in one process, on the same numbering: the points are selected from \a file as
  * pcl_wrap selects them, the vertices (all but the \a hidden points) numbered along the same
  * Z-order curve, the tetrahedra sorted by their vertex sets and each turned to the same even
  * permutation of its vertices. X is the closure of its tetrahedra and of W's simplices on none of
  * them (the \a sheets, and the dangling edges and isolated vertices of \a raw_w, all in indices
  * of S). So the output is pcl_wrap's, triangle for triangle.
  * \param[in] solid every tile's, in any order
  * \param[in,out] result its surface, copies, complex and statistics of these stages set */
void
surfaceOnRoot (const apps::PointFile& file, const std::vector<PointIndex>& hidden, TileSolid solid,
               const std::vector<std::array<std::uint32_t, 3>>& sheets, const WrapSurface& raw_w,
               const WrapParameters& parameters, WrapResult& result, detail::StageClock& clock);

/** \brief Sets WrapResult::off_surface of \a result, the output over \a input_points points, as
  * one process does: every point neither skipped, nor a duplicate, nor hidden, that no triangle
  * of its surface has. */
void
recordPointsOff (std::size_t input_points, WrapResult& result);

} // namespace pcl_wrap::mpi

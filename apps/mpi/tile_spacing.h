// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "tile_complex.h"

#include <mpi.h>

namespace pcl_wrap::mpi
{

/** \brief The median nearest-neighbour distance of the points used, exactly as one process
  * measures it (delaunay/spacing.h): WrapStatistics::spacing, and the unit of --radius-rel.
  *
  * Each tile measures its own vertices: their stars are whole here, so each one's nearest
  * neighbour, a Delaunay neighbour, is among its edges. The median is then selected across the
  * ranks, without gathering the distances, by bisection on the squared distances' bits (ordered as
  * integers, as non-negative doubles are): each step sums, over the ranks, how many are at most
  * the middle. Called by every rank. */
double
tileMedianSpacing (MPI_Comm comm, const TileComplex& tile);

} // namespace pcl_wrap::mpi

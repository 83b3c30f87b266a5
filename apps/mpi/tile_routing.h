// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "star_completion.h"
#include "tile_input.h"
#include "tile_partition.h"
#include "tile_reach.h"

#include <mpi.h>

#include <array>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief A rank's tile, once every point has gone to the tile its position falls in. */
struct RoutedTile
{
  TilePoints points;      ///< the tile's points of S, in input order
  std::vector<Box> boxes; ///< every tile's bounding box, on every rank
  /** (dropped duplicate, the point at the same position that stays), for this tile's points:
    * as for one process, the largest weight stays, then the smallest index. */
  std::vector<std::array<PointIndex, 2>> duplicates;
  double w_max = 0;          ///< the largest weight in S (at least 0)
  bool equal_weights = true; ///< every point of S has the same weight
};

/** \brief The tiles of \a share's points: cuts from a sample of every rank's points (those whose
  * index is a multiple of a stride, so the sample depends on the input alone), then one
  * exchange. */
RoutedTile
routeToTiles (MPI_Comm comm, InputShare share);

} // namespace pcl_wrap::mpi

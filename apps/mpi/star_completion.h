// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "tile_reach.h"

#include "delaunay/regular_triangulation.h"

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief A point of S as it travels between ranks. */
struct PointRecord
{
  Point3 position;
  double weight;
  std::uint32_t index; ///< in S, the same on every rank
  std::uint32_t tile;  ///< the tile (rank) that owns it
};

/** \brief The points a rank holds: its tile's own points first, then the ghosts other ranks sent. */
struct TilePoints
{
  std::vector<PointRecord> points;
  std::size_t own = 0;
};

struct StarCompletionStatistics
{
  int rounds = 0;
  std::size_t ghosts = 0; ///< points received from other tiles
  std::size_t bytes_sent = 0;
};

/** \brief Sends and receives ghost points until every tetrahedron (and hull facet) of this rank's
  * regular triangulation that has an own vertex is one of Del S; returns that triangulation.
  *
  * Each round every rank adds what it received to its triangulation (GrowingTriangulation) and
  * sends, for each of its tetrahedra with a vertex of its own or of the receiver's tile, the
  * tetrahedron's vertices to every other tile whose box its reach meets (TileReach). It stops when no rank receives a point it lacks. Why
  * that suffices: if a tetrahedron t of rank r with own vertex v had a point q of tile s in its
  * (symbolically perturbed) orthoball, t's reach meets s's box, so s holds t's vertices and q. In
  * a regular triangulation the vertices inside any orthosphere are connected (they are the lower
  * hull's vertices below a hyperplane after lifting), so s's triangulation has an edge from v to
  * a vertex u inside t's orthoball. The tetrahedra on that edge reach v, in r's box, so s sends u
  * to r; once r holds u, t is no longer in r's triangulation. A hull facet is the limit of a
  * ball, with the same argument. \a w_max is the largest weight in S; \a equal_weights says
  * whether all of S's weights are equal. */
detail::Triangulation
completeStars (MPI_Comm comm, TilePoints& tile, const std::vector<Box>& boxes, double w_max, bool equal_weights,
               StarCompletionStatistics& statistics);

} // namespace pcl_wrap::mpi

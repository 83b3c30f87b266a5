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
  std::size_t ghosts = 0;     ///< points received from other tiles
  std::size_t questions = 0;  ///< tetrahedra asked about, per tile asked
  std::size_t by_nearest = 0; ///< questions answered by the nearest point (TileSearch)
  std::size_t bytes_sent = 0;
};

/** \brief Sends and receives ghost points until every tetrahedron (and hull facet) of this rank's
  * regular triangulation that has an own vertex is one of Del S; returns that triangulation.
  *
  * Each round every rank adds what it received to its triangulation (GrowingTriangulation) and
  * sends, for each of its tetrahedra:
  * - with a vertex of tile s, all its vertices to s (s learns its points' neighbours here);
  * - with an own vertex and none of tile s, whose reach (TileReach) may meet s's box: a question
  *   to s, whether one of its points may be in that reach (TileSearch); if s says yes, the own
  *   vertices go to s. A tetrahedron asks a tile once: the tile's own points do not change.
  * It stops when no rank receives a point it lacks. Why that suffices: let a tetrahedron t of rank
  * r, with own vertex v, have a point q of tile s inside its (symbolically perturbed)
  * orthosphere. t's reach holds q, so s said yes and holds v and q. After lifting, the points inside an
  * orthosphere are those below a hyperplane; tilted about v's lift until t's other vertices are
  * just above it, the hyperplane has below it v and the points strictly inside, and the vertices
  * of a convex polytope on one side of a hyperplane are connected by its edges (here the edges
  * of s's triangulation). So s's triangulation has an edge from v to
  * a point u strictly inside t's orthosphere; s sends r the vertices of the tetrahedra on v, u
  * among them, and once r holds u, t is not in r's triangulation. A hull facet is the limit of a
  * ball, with the same argument. \a w_max is the largest weight in S; \a equal_weights says
  * whether all of S's weights are equal. */
detail::Triangulation
completeStars (MPI_Comm comm, TilePoints& tile, const std::vector<Box>& boxes, double w_max, bool equal_weights,
               StarCompletionStatistics& statistics);

} // namespace pcl_wrap::mpi

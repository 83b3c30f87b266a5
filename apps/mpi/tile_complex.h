// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "star_completion.h"

#include "delaunay/simplicial_complex.h"
#include "delaunay/tetrahedra.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief One rank's part of Del S: the tetrahedra of its completed triangulation that have a vertex
  * of its own (each is one of Del S, with its whole star), their faces, and how they meet.
  *
  * A simplex *belongs* to the tile of its vertex with the smallest index in S. Every coface of a
  * simplex that belongs here contains that vertex, so it is here too: its class, its flow and its
  * coface counts are those of Del S. The other simplices here are the rim of the part, read but
  * never decided on. */
class TileComplex
{
public:
  TileComplex (const TilePoints& tile, const detail::Triangulation& triangulation, std::uint32_t rank);

  const detail::SimplicialComplex& complex () const { return complex_; }
  /** \brief Hands the complex's coface counts over to a subcomplex (SimplicialComplex). */
  std::array<detail::FilledInParallel<std::uint32_t>, 3> releaseCofaceCounts ()
  {
    return complex_.releaseCofaceCounts ();
  }
  const detail::Tetrahedra& tetrahedra () const { return tetrahedra_; }
  const std::vector<Point3>& positions () const { return positions_; }
  const std::vector<double>& weights () const { return weights_; }
  /** \brief Per vertex: its index in S and its tile. */
  std::uint32_t indexOf (std::uint32_t vertex) const { return index_[vertex]; }
  std::uint32_t tileOf (std::uint32_t vertex) const { return tile_[vertex]; }

  /** \brief The tile that \a s belongs to. */
  std::uint32_t owner (detail::Simplex s) const;
  bool belongsHere (detail::Simplex s) const { return owner (s) == rank_; }

  /** \brief The simplex with these vertices (indices in S), which must have a vertex of this
    * tile; NO_SIMPLEX in its id if there is none here. */
  detail::Simplex find (int dim, const std::uint32_t* indices) const;

private:
  std::uint32_t rank_;
  std::vector<Point3> positions_;
  std::vector<double> weights_;
  std::vector<std::uint32_t> index_, tile_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> vertex_of_index_; // (index, vertex), sorted
  detail::SimplicialComplex complex_;
  detail::Tetrahedra tetrahedra_;
};

} // namespace pcl_wrap::mpi

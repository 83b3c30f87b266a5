// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_complex.h"

#include <algorithm>

namespace pcl_wrap::mpi
{

using detail::NO_NEIGHBOUR;
using detail::NO_SIMPLEX;
using detail::Simplex;

TileComplex::TileComplex (const TilePoints& tile, const detail::Triangulation& triangulation, std::uint32_t rank)
  : rank_ (rank)
{
  const std::size_t count = triangulation.top_simplices.size () / 4;
  const auto record = [&] (std::uint32_t v) -> const PointRecord& {
    return tile.points[triangulation.point_of_vertex[v]];
  };
  // Keep the tetrahedra with an own vertex; number their vertices and themselves densely.
  constexpr std::uint32_t NONE = ~std::uint32_t (0);
  std::vector<std::uint32_t> kept_id (count, NONE), vertex_id (triangulation.point_of_vertex.size (), NONE);
  std::uint32_t kept = 0;
  for (std::size_t t = 0; t < count; ++t)
  {
    const std::uint32_t* v = &triangulation.top_simplices[4 * t];
    if (std::none_of (v, v + 4, [&] (std::uint32_t u) { return record (u).tile == rank; }))
      continue;
    kept_id[t] = kept++;
    for (int i = 0; i < 4; ++i)
      if (vertex_id[v[i]] == NONE)
      {
        vertex_id[v[i]] = static_cast<std::uint32_t> (index_.size ());
        const PointRecord& r = record (v[i]);
        positions_.push_back (r.position);
        weights_.push_back (r.weight);
        index_.push_back (r.index);
        tile_.push_back (r.tile);
      }
  }
  vertex_of_index_.reserve (index_.size ());
  for (std::uint32_t v = 0; v < index_.size (); ++v)
    vertex_of_index_.emplace_back (index_[v], v);
  std::sort (vertex_of_index_.begin (), vertex_of_index_.end ());
  detail::FilledInParallel<std::uint32_t> tetrahedra (4 * std::size_t (kept)), neighbours (4 * std::size_t (kept));
  for (std::size_t t = 0; t < count; ++t)
    if (kept_id[t] != NONE)
      for (int i = 0; i < 4; ++i)
      {
        const std::size_t at = 4 * std::size_t (kept_id[t]) + i;
        tetrahedra[at] = vertex_id[triangulation.top_simplices[4 * t + i]];
        const std::uint32_t across = triangulation.neighbours[4 * t + i];
        neighbours[at] = across == NO_NEIGHBOUR ? NO_NEIGHBOUR : kept_id[across];
      }
  complex_ =
      detail::SimplicialComplex (3, static_cast<std::uint32_t> (index_.size ()), std::move (tetrahedra), neighbours);
  tetrahedra_ = detail::Tetrahedra (std::move (neighbours));
  tetrahedra_.attach (complex_);
}

std::uint32_t
TileComplex::owner (Simplex s) const
{
  const std::uint32_t* v = complex_.vertices (s.dim, s.id);
  std::uint32_t lowest = v[0];
  for (int i = 1; i <= s.dim; ++i)
    if (index_[v[i]] < index_[lowest])
      lowest = v[i];
  return tile_[lowest];
}

Simplex
TileComplex::find (int dim, const std::uint32_t* indices) const
{
  std::uint32_t vertices[4];
  constexpr std::uint32_t NONE_HOME = ~std::uint32_t (0);
  std::uint32_t home = NONE_HOME;
  for (int i = 0; i <= dim; ++i)
  {
    const auto found = std::lower_bound (vertex_of_index_.begin (), vertex_of_index_.end (),
                                         std::make_pair (indices[i], std::uint32_t (0)));
    if (found == vertex_of_index_.end () || found->first != indices[i])
      return {dim, NO_SIMPLEX};
    vertices[i] = found->second;
    if (tile_[vertices[i]] == rank_)
      home = vertices[i];
  }
  if (home == NONE_HOME)
    return {dim, NO_SIMPLEX};
  if (dim == 0)
    return {0, home};
  // Every simplex on an own vertex is a face of a tetrahedron in that vertex's (complete) star.
  thread_local detail::Star star;
  const auto [t, mask] = tetrahedra_.faceAround (home, vertices, dim + 1, star);
  return t == detail::NO_TETRAHEDRON ? Simplex{dim, NO_SIMPLEX} : complex_.face (3, t, mask);
}

} // namespace pcl_wrap::mpi

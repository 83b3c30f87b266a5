// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "input_indices.h"

#include <algorithm>
#include <utility>

namespace pcl_wrap::detail
{

void
InputIndices::takeSplit (ManifoldSplit& split, Boundary& w, std::size_t input_points, WrapResult& result)
{
  w.triangles = std::move (split.triangles);
  result.copies.clear ();
  result.copies.reserve (split.copy_of.size ());
  for (std::size_t k = 0; k < split.copy_of.size (); ++k)
  {
    result.copies.push_back (of_vertex_[split.copy_of[k]]);
    of_vertex_.push_back (static_cast<PointIndex> (input_points + k));
  }
  WrapStatistics& stats = result.statistics;
  stats.pinch_edges_split = split.pinch_edges;
  stats.pinch_vertices_split = split.pinch_vertices;
  stats.sheet_triangles_doubled = split.sheet_triangles;
}

WrapSurface
InputIndices::surface (const Boundary& w) const
{
  const InputIndices& in = *this;
  WrapSurface surface;
  surface.triangles.reserve (w.triangles.size ());
  for (const auto& t : w.triangles)
    surface.triangles.push_back ({in (t[0]), in (t[1]), in (t[2])});
  for (const auto& e : w.dangling_edges)
    surface.dangling_edges.push_back ({std::min (in (e[0]), in (e[1])), std::max (in (e[0]), in (e[1]))});
  for (std::uint32_t v : w.isolated_vertices)
    surface.isolated_vertices.push_back (in (v));
  return surface;
}

std::array<SimplexList, 4>
InputIndices::complex (const SimplicialComplex& complex, const Classification& classification,
                       const Subcomplex& x) const
{
  std::array<SimplexList, 4> lists;
  for (int k = 0; k <= 3; ++k)
  {
    SimplexList& list = lists[k];
    list.vertices.reserve ((k + 1) * complex.size (k));
    list.classes.assign (classification.classes[k].begin (), classification.classes[k].end ());
    list.in_x.resize (complex.size (k));
    for (SimplexId s = 0; s < complex.size (k); ++s)
    {
      list.in_x[s] = x.contains ({k, s});
      for (int i = 0; i <= k; ++i)
        list.vertices.push_back (of_vertex_[complex.vertex (k, s, i)]);
    }
  }
  return lists;
}

void
InputIndices::recordPointsOff (WrapResult& result, std::size_t input_points) const
{
  std::vector<std::uint8_t> on (input_points, 0);
  for (const auto& t : result.surface.triangles)
    for (PointIndex p : t)
      on[p < input_points ? p : result.copies[p - input_points]] = 1;
  std::vector<PointIndex>& off = result.off_surface;
  off.clear ();
  for (std::size_t v = 0; v < vertices_; ++v)
    if (!on[of_vertex_[v]])
      off.push_back (of_vertex_[v]);
  std::sort (off.begin (), off.end ());
  result.statistics.points_off_surface = off.size ();
}

std::vector<PointIndex>
InputIndices::sortedPoints (const std::vector<std::uint32_t>& vertices) const
{
  std::vector<PointIndex> points;
  points.reserve (vertices.size ());
  for (std::uint32_t v : vertices)
    points.push_back (of_vertex_[v]);
  std::sort (points.begin (), points.end ());
  return points;
}

InputIndices
InputIndices::reindexed (const std::function<std::uint32_t (std::uint32_t)>& index) const
{
  InputIndices out (of_vertex_);
  out.vertices_ = vertices_;
  for (PointIndex& p : out.of_vertex_)
    p = index (p);
  return out;
}

} // namespace pcl_wrap::detail

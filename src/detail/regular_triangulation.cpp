// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "regular_triangulation.h"

#include "cgal_kernel.h"

#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Hilbert_sort_3.h>
#include <CGAL/Hilbert_policy_tags.h>
#include <CGAL/property_map.h>

#include <numeric>

#include <utility>

namespace pcl_wrap::detail
{
namespace
{

using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<
    std::uint32_t, Kernel, CGAL::Regular_triangulation_vertex_base_3<Kernel>>;
// Hidden points are found from the vertex set afterwards, so cells need not store them. The info
// numbers the finite cells, to name neighbours.
using CellBase = CGAL::Triangulation_cell_base_with_info_3<
    std::uint32_t, Kernel,
    CGAL::Regular_triangulation_cell_base_3<Kernel, CGAL::Triangulation_cell_base_3<Kernel>, CGAL::Discard_hidden_points>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Regular = CGAL::Regular_triangulation_3<Kernel, Tds>;

} // namespace

Triangulation
triangulate (const std::vector<Point3>& positions, const std::vector<double>& weights)
{
  std::vector<std::pair<WeightedPoint, std::uint32_t>> input;
  input.reserve (positions.size ());
  for (std::uint32_t i = 0; i < positions.size (); ++i)
  {
    const Point3& p = positions[i];
    input.emplace_back (WeightedPoint (BarePoint (p[0], p[1], p[2]), weights[i]), i);
  }
  Regular rt;
  rt.insert (input.begin (), input.end ()); // spatially sorted insertion
  input = {};

  Triangulation t;
  t.dimension = rt.number_of_vertices () == 0 ? -1 : rt.dimension ();

  // Vertex ids along a Hilbert curve: neighbours in space are neighbours in every array
  // indexed by vertex (and so by edge and triangle), which keeps the later stages in cache.
  // The numbering depends only on the points, never on CGAL's internals.
  std::vector<BarePoint> bare;
  bare.reserve (positions.size ());
  for (const Point3& p : positions)
    bare.emplace_back (p[0], p[1], p[2]);
  std::vector<std::uint32_t> curve (positions.size ());
  std::iota (curve.begin (), curve.end (), 0u);
  using ByIndex = CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::Pointer_property_map<BarePoint>::type>;
  CGAL::Hilbert_sort_3<ByIndex, CGAL::Hilbert_sort_median_policy> (ByIndex (CGAL::make_property_map (bare.data ()))) (
      curve.begin (), curve.end ());
  bare = {};

  constexpr std::uint32_t ABSENT = ~std::uint32_t (0);
  std::vector<std::uint32_t> vertex_of_point (positions.size (), ABSENT);
  for (auto v = rt.finite_vertices_begin (); v != rt.finite_vertices_end (); ++v)
    vertex_of_point[v->info ()] = 0;
  for (std::uint32_t i : curve)
    if (vertex_of_point[i] != ABSENT)
    {
      vertex_of_point[i] = static_cast<std::uint32_t> (t.point_of_vertex.size ());
      t.point_of_vertex.push_back (i);
    }
  for (std::uint32_t i = 0; i < positions.size (); ++i)
    if (vertex_of_point[i] == ABSENT)
      t.hidden.push_back (i);
  const auto id = [&] (Regular::Vertex_handle v) { return vertex_of_point[v->info ()]; };

  auto& top = t.top_simplices;
  switch (t.dimension)
  {
  case 3:
  {
    std::uint32_t cells = 0;
    for (auto c = rt.finite_cells_begin (); c != rt.finite_cells_end (); ++c)
      c->info () = cells++;
    top.reserve (4 * std::size_t (cells));
    t.neighbours.reserve (4 * std::size_t (cells));
    for (auto c = rt.finite_cells_begin (); c != rt.finite_cells_end (); ++c)
      for (int i = 0; i < 4; ++i)
      {
        top.push_back (id (c->vertex (i)));
        const auto n = c->neighbor (i);
        t.neighbours.push_back (rt.is_infinite (n) ? NO_NEIGHBOUR : n->info ());
      }
    break;
  }
  case 2:
    for (auto f = rt.finite_facets_begin (); f != rt.finite_facets_end (); ++f)
      for (int i = 0; i < 3; ++i)
        top.push_back (id (f->first->vertex (i)));
    break;
  case 1:
    for (auto e = rt.finite_edges_begin (); e != rt.finite_edges_end (); ++e)
    {
      top.push_back (id (e->first->vertex (e->second)));
      top.push_back (id (e->first->vertex (e->third)));
    }
    break;
  case 0:
    top.push_back (0);
    break;
  default:
    break;
  }
  return t;
}

} // namespace pcl_wrap::detail

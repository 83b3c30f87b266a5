// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap_report.h"

#include "mesh_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <vector>

namespace pcl_wrap::apps
{
namespace
{

constexpr SimplexClass CLASSES[3] = {SimplexClass::centered, SimplexClass::confident, SimplexClass::equivocal};

template <std::size_t N>
void
writeTuples (std::ostream& out, const std::vector<std::array<PointIndex, N>>& tuples)
{
  out << '[';
  for (std::size_t i = 0; i < tuples.size (); ++i)
  {
    out << (i ? ",[" : "[");
    for (std::size_t j = 0; j < N; ++j)
      out << (j ? "," : "") << tuples[i][j];
    out << ']';
  }
  out << ']';
}

template <class T>
void
writeList (std::ostream& out, const std::vector<T>& values)
{
  out << '[';
  for (std::size_t i = 0; i < values.size (); ++i)
    out << (i ? "," : "") << values[i];
  out << ']';
}

template <std::size_t N>
std::vector<std::array<PointIndex, N>>
sortedSimplices (const std::vector<PointIndex>& flat)
{
  std::vector<std::array<PointIndex, N>> out (flat.size () / N);
  for (std::size_t s = 0; s < out.size (); ++s)
  {
    std::copy_n (flat.begin () + N * s, N, out[s].begin ());
    std::sort (out[s].begin (), out[s].end ());
  }
  std::sort (out.begin (), out.end ());
  return out;
}

/** {"triangles", "edges", "vertices" of a surface, every list sorted and triangles rotated to start
  * at their smallest index (their orientation kept); the object is left open. */
void
writeSurface (std::ostream& out, const WrapSurface& surface)
{
  auto triangles = surface.triangles;
  for (auto& t : triangles)
    std::rotate (t.begin (), std::min_element (t.begin (), t.end ()), t.end ());
  std::sort (triangles.begin (), triangles.end ());
  auto edges = surface.dangling_edges;
  for (auto& e : edges)
    std::sort (e.begin (), e.end ());
  std::sort (edges.begin (), edges.end ());
  auto vertices = surface.isolated_vertices;
  std::sort (vertices.begin (), vertices.end ());
  out << "{\"triangles\":";
  writeTuples (out, triangles);
  out << ",\"edges\":";
  writeTuples (out, edges);
  out << ",\"vertices\":";
  writeList (out, vertices);
}

} // namespace

void
writeComplexJson (std::ostream& out, const WrapResult& result, std::size_t num_points)
{
  std::vector<PointIndex> duplicates;
  for (const auto& d : result.duplicates)
    duplicates.push_back (d.first);
  out << std::setprecision (17) << "{\"n\":" << num_points << ",\"hidden\":";
  writeList (out, result.hidden);
  out << ",\"skipped\":";
  writeList (out, result.skipped);
  out << ",\"duplicates\":";
  writeList (out, duplicates);

  out << ",\"X\":{\"0\":";
  writeTuples (out, sortedSimplices<1> (result.xSimplices (0)));
  out << ",\"1\":";
  writeTuples (out, sortedSimplices<2> (result.xSimplices (1)));
  out << ",\"2\":";
  writeTuples (out, sortedSimplices<3> (result.xSimplices (2)));
  out << ",\"3\":";
  writeTuples (out, sortedSimplices<4> (result.xSimplices (3)));

  out << "},\"W\":";
  writeSurface (out, result.w);
  out << "},\"surface\":";
  writeSurface (out, result.surface);
  out << ",\"copies\":";
  writeList (out, result.copies);

  // The wrap filtration: each simplex of the basic X with the size of the sink whose deletion
  // removes it (null: none does), and every sink size.
  if (!result.filtration.empty ())
  {
    out << "},\"filtration\":{\"sink_sizes\":";
    writeList (out, result.filtration.sinkSizes ());
    for (int k = 0; k <= 3; ++k)
    {
      const SimplexList& list = result.complex[k];
      out << ",\"" << k << "\":[";
      bool first = true;
      for (std::size_t s = 0; s < list.size () && !list.values.empty (); ++s)
        if (list.values[s] < std::numeric_limits<double>::infinity ()) // in the basic X
        {
          out << (first ? "[" : ",[");
          first = false;
          for (int i = 0; i <= k; ++i)
            out << list.vertices[(k + 1) * s + i] << ',';
          std::isfinite (list.values[s]) ? out << list.values[s] : out << "null";
          out << ']';
        }
      out << ']';
    }
  }
  const WrapStatistics& st = result.statistics;
  out << "},\"deletion\":{\"sinks\":" << st.sinks << ",\"deleted\":" << st.sinks_deleted
      << ",\"enclosed\":" << st.sinks_enclosed << ",\"not_principal\":" << st.sinks_not_principal;
  out << "},\"class_counts\":{";
  for (int k = 0; k <= 3; ++k)
  {
    out << (k ? "," : "") << '"' << k << "\":{";
    for (int c = 0; c < 3; ++c)
      out << (c ? "," : "") << '"' << toString (CLASSES[c]) << "\":" << result.statistics.simplices[k][c];
    out << '}';
  }
  out << "}}\n";
}

void
printSummary (std::ostream& out, const WrapStatistics& s)
{
  std::size_t del[4] = {0, 0, 0, 0};
  for (int k = 0; k <= 3; ++k)
    for (int c = 0; c < 3; ++c)
      del[k] += s.simplices[k][c];
  out << "points:        " << s.points_input << " given, " << s.points_used << " used, " << s.points_skipped
      << " skipped (non-finite), " << s.points_duplicate << " duplicate, " << s.points_hidden << " hidden";
  out << "; " << s.points_off_surface << " off the surface";
  if (s.points_apart > 0)
    out << " (" << s.points_apart << " apart from all others)";
  out << "\n"
      << "Del S:         dimension " << s.triangulation_dimension << ", " << del[0] << " vertices, " << del[1]
      << " edges, " << del[2] << " triangles, " << del[3] << " tetrahedra\n"
      << "sinks:         ";
  for (int k = 0; k <= 3; ++k)
    out << (k ? ", " : "") << s.simplices[k][0] << " centered "
        << (k == 0   ? "vertices"
            : k == 1 ? "edges"
            : k == 2 ? "triangles"
                     : "tetrahedra");
  if (std::isfinite (s.delta) || s.sinks_deleted > 0)
  {
    out << "\ndeletion:      spacing " << s.spacing << ", threshold " << s.delta << " (radius "
        << std::sqrt (std::max (s.delta, 0.0)) << "), " << s.sinks_deleted << " of " << s.sinks << " sinks deleted, "
        << s.sinks_enclosed << " enclosed, " << s.sinks_not_principal << " not principal; largest sinks";
    for (double size : s.largest_sinks)
      out << ' ' << size;
  }
  out << "\nX:             " << s.x_simplices[0] << " vertices, " << s.x_simplices[1] << " edges, " << s.x_simplices[2]
      << " triangles, " << s.x_simplices[3] << " tetrahedra after " << s.collapses << " collapses\n"
      << "W:             " << s.w_triangles << " triangles, " << s.w_dangling_edges << " dangling edges, "
      << s.w_isolated_vertices << " isolated vertices";
  if (s.pinch_edges_split + s.pinch_vertices_split + s.sheet_triangles_doubled > 0)
    out << "; split " << s.pinch_edges_split << " pinch edges, " << s.pinch_vertices_split << " pinch vertices, "
        << s.sheet_triangles_doubled << " sheet triangles doubled";
  if (s.single_layer && s.sheet_triangles_doubled > 0)
    out << "; the points are a single layer: a two-sided shell, " << s.bridge_simplices << " simplices tie its pieces";
  else if (s.single_layer)
    out << "; the points are a single layer: one open sheet";
  if (s.surface_is_w)
    out << "; the output is W, split: the labelled solid's surface would leave more of its points off";
  out << "\n"
      << "time:          " << std::fixed << std::setprecision (3) << s.total_seconds << " s (";
  for (std::size_t i = 0; i < s.timings.size (); ++i)
    out << (i ? ", " : "") << s.timings[i].stage << ' ' << s.timings[i].seconds;
  out << ")\n" << std::defaultfloat;
}

std::size_t
writeSurfaceMesh (const std::string& path, const PointFile& file, const WrapResult& result)
{
  const std::size_t num_points = file.points.size ();
  std::vector<bool> skipped (num_points, false);
  for (const PointIndex i : result.skipped)
    skipped[i] = true;
  std::vector<PointIndex> rows;
  std::vector<PointIndex> vertex_of (num_points + result.copies.size (), 0);
  for (PointIndex i = 0; i < num_points; ++i)
    if (!skipped[i])
    {
      vertex_of[i] = static_cast<PointIndex> (rows.size ());
      rows.push_back (i);
    }
  for (std::size_t j = 0; j < result.copies.size (); ++j)
  {
    vertex_of[num_points + j] = static_cast<PointIndex> (rows.size ());
    rows.push_back (result.copies[j]);
  }
  std::vector<std::array<PointIndex, 3>> triangles = result.surface.triangles;
  for (auto& t : triangles)
    for (PointIndex& v : t)
      v = vertex_of[v];
  std::vector<Point3> vertices;
  vertices.reserve (rows.size ());
  for (const PointIndex r : rows)
    vertices.push_back (file.points[r]);
  writeMesh (path, vertices, triangles, file.attributes.rows (rows));
  return vertices.size ();
}

} // namespace pcl_wrap::apps

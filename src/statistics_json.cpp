// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include <pcl_wrap/statistics_json.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

namespace pcl_wrap
{

std::string
statisticsJson (const WrapResult& result)
{
  constexpr SimplexClass CLASSES[3] = {SimplexClass::centered, SimplexClass::confident, SimplexClass::equivocal};
  const WrapStatistics& s = result.statistics;
  std::ostringstream out;
  const auto writeList = [] (std::ostream& to, const auto& values) {
    const char* separator = "[";
    for (const auto& v : values)
      to << std::exchange (separator, ",") << v;
    to << (values.empty () ? "[]" : "]");
  };
  const auto number = [&] (double x) -> std::ostream& {
    return std::isfinite (x) ? out << x : out << "null"; // JSON has no infinity
  };
  out << std::setprecision (9) << "{\"points\":{\"input\":" << s.points_input << ",\"used\":" << s.points_used
      << ",\"skipped\":" << s.points_skipped << ",\"duplicate\":" << s.points_duplicate
      << ",\"hidden\":" << s.points_hidden << ",\"apart\":" << s.points_apart
      << ",\"off_surface\":" << s.points_off_surface << "},\"hidden\":";
  writeList (out, result.hidden);
  out << ",\"apart\":";
  writeList (out, result.apart);
  out << ",\"off_surface\":";
  writeList (out, result.off_surface);
  out << ",\"triangulation_dimension\":" << s.triangulation_dimension << ",\"simplices\":{";
  for (int k = 0; k <= 3; ++k)
  {
    out << (k ? "," : "") << '"' << k << "\":{";
    for (int c = 0; c < 3; ++c)
      out << (c ? "," : "") << '"' << toString (CLASSES[c]) << "\":" << s.simplices[k][c];
    out << '}';
  }
  out << "},\"x_simplices\":{";
  for (int k = 0; k <= 3; ++k)
    out << (k ? "," : "") << '"' << k << "\":" << s.x_simplices[k];
  out << "},\"spacing\":" << s.spacing << ",\"deletion\":{\"delta\":";
  number (s.delta) << ",\"largest_sinks\":";
  writeList (out, s.largest_sinks);
  out << ",\"sinks\":" << s.sinks << ",\"deleted\":" << s.sinks_deleted << ",\"enclosed\":" << s.sinks_enclosed
      << ",\"not_principal\":" << s.sinks_not_principal;
  out << "},\"manifold\":{\"pinch_edges_split\":" << s.pinch_edges_split
      << ",\"pinch_vertices_split\":" << s.pinch_vertices_split
      << ",\"sheet_triangles_doubled\":" << s.sheet_triangles_doubled
      << ",\"single_layer\":" << (s.single_layer ? "true" : "false") << ",\"bridge_simplices\":" << s.bridge_simplices
      << ",\"copies\":";
  writeList (out, result.copies);
  out << "},\"tetrahedra_moved\":" << s.tetrahedra_moved << ",\"surface_is_w\":" << (s.surface_is_w ? "true" : "false")
      << ",\"collapses\":" << s.collapses << ",\"perturbations\":" << s.perturbations
      << ",\"w\":{\"triangles\":" << s.w_triangles << ",\"dangling_edges\":" << s.w_dangling_edges
      << ",\"isolated_vertices\":" << s.w_isolated_vertices << "},\"timings\":{";
  for (const StageTiming& t : s.timings)
    out << '"' << t.stage << "\":" << t.seconds << ',';
  out << "\"total\":" << s.total_seconds << "}}";
  return out.str ();
}

} // namespace pcl_wrap

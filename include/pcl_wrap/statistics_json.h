// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/wrap_result.h>

#include <string>

namespace pcl_wrap
{

/** \brief The statistics of \a result as one JSON object, the same keys in every interface (the
  * CLI's --stats-json, Python's WrapResult.statistics):
  * {"points": {"input", "used", "skipped", "duplicate", "hidden", "apart", "off_surface"},
  *  "hidden": [indices], "apart": [indices], "off_surface": [indices],
  *  "triangulation_dimension", "simplices": {"0".."3": {class: count}}, "x_simplices": {"0".."3"},
  *  "spacing", "deletion": {"delta" (null: none), "largest_sinks", "sinks", "deleted", "enclosed",
  *  "not_principal"}, "manifold": {"pinch_edges_split", "pinch_vertices_split",
  *  "sheet_triangles_doubled", "single_layer", "bridge_simplices", "copies": [indices]},
  *  "tetrahedra_moved", "surface_is_w", "collapses", "perturbations", "w": {"triangles", "dangling_edges", "isolated_vertices"},
  *  "timings": {"<stage>": seconds, ..., "total": seconds}}. */
std::string
statisticsJson (const WrapResult& result);

} // namespace pcl_wrap

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "point_file.h"

#include <pcl_wrap/wrap_result.h>

#include <cstddef>
#include <ostream>
#include <string>

namespace pcl_wrap::apps
{

/** \brief The complex as JSON: {"n", "hidden", "skipped", "duplicates", "X": {"0".."3"},
  * "W": {"triangles", "edges", "vertices"} (the paper's W = Bd X, whatever the output),
  * "surface": {"triangles", "edges", "vertices", "copies"} (the output), "filtration":
  * {"sink_sizes", "0".."3": each simplex of X as [vertices..., value or null]} (when computed),
  * "deletion": {"sinks", "deleted", "enclosed", "not_principal"}, "class_counts"}. Every simplex
  * of X and every list sorted; triangles keep their orientation (rotated to start at their
  * smallest index). \a result needs the complex (WrapParameters::keep_complex). */
void
writeComplexJson (std::ostream& out, const WrapResult& result, std::size_t num_points);

/** \brief A short human summary of the statistics. */
void
printSummary (std::ostream& out, const WrapStatistics& stats);

/** \brief Writes \a result's output surface to the mesh file \a path (writeMesh()): its vertices are
  * \a file's points that were not skipped, in input order, then the sources of the copies, each
  * with its attributes. Returns the number of vertices written. */
std::size_t
writeSurfaceMesh (const std::string& path, const PointFile& file, const WrapResult& result);

} // namespace pcl_wrap::apps

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/wrap_result.h>

#include <cstddef>
#include <ostream>

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

} // namespace pcl_wrap::apps

// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace pcl_wrap::apps
{

/** \brief The vertices of an Object File Format (.off) text. */
struct OffVertices
{
  bool normals = false, colours = false; ///< what the header ([ST][C][N][4][n]OFF) says a vertex has
  std::size_t needed = 3;                ///< numbers a vertex line needs: x y z [nx ny nz] [r g b]
  std::vector<double> values;            ///< every number of each vertex line, in order
  std::vector<std::size_t> begin;        ///< per vertex, where its numbers start in values; then the end
  std::string error;                     ///< the first problem ("line N: ..."; then no vertices)
};

/** \brief Reads the header and the vertex lines of an .off text as one reading a line at a time
  * with parseNumbers() would (a line with no number, blank or a comment, is skipped), the vertex
  * lines on all threads, a window of text at a time; the faces that follow are not read. The
  * values are those of std::strtod, bit for bit; the error is the first one in the file.
  * \param[in] window_bytes the most text read at once
  * \param[in] chunk_bytes how much text a task reads, at least (on to the end of a line) */
OffVertices
readOffStream (std::istream& in, std::size_t window_bytes = std::size_t (1) << 25,
               std::size_t chunk_bytes = std::size_t (1) << 18);

} // namespace pcl_wrap::apps

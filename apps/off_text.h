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

/** \brief The header of an .off text: its keyword and its vertex count. */
struct OffHeader
{
  bool normals = false, colours = false; ///< what the keyword ([ST][C][N][4][n]OFF) says a vertex has
  std::size_t needed = 3;                ///< numbers a vertex line needs: x y z [nx ny nz] [r g b]
  std::size_t vertices = 0;              ///< the vertex count
  std::size_t lines = 0;                 ///< the lines it takes, up to the count's
  std::string error;                     ///< the first problem (then nothing else is set)
};

/** \brief Reads the header of an .off text from \a in, a line at a time: the keyword on the first
  * line with content, then the vertex count, on the keyword's line or the next line with numbers. */
OffHeader
readOffHeader (std::istream& in);

/** \brief Reads lines from \a in up to the next one with numbers (a blank line or a comment has
  * none) and parses them into \a numbers; \a lines counts the lines read. False, with \a problem,
  * at the end of the text ("ends before WHAT") or a line that is not numbers ("line N: not a number
  * in WHAT"). */
bool
nextNumbersLine (std::istream& in, std::vector<double>& numbers, std::size_t& lines, const char* what,
                 std::string& problem);

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
